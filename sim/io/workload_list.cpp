#include "io/workload_list.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "common/input_error.hpp"
#include "io/trace_reader.hpp"

namespace girtd {

std::vector<std::string> sample_workloads() { return read_input_list(kWorkloadList); }

std::vector<std::string> read_input_list(const std::string& list) {
  std::ifstream in(list);
  if (!in) throw InputError(list, 0, "no such file: run from the repository root");
  std::vector<std::string> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    line.erase(0, line.find_first_not_of(" \t"));
    line.erase(line.find_last_not_of(" \t\r") + 1);
    if (line.empty() || line[0] == '#') continue;
    if (!std::filesystem::is_regular_file(line)) throw InputError(list, n, "'" + line + "': no such file");
    out.push_back(line);
  }
  return out;
}

std::vector<std::string> sample_traces_at(const std::vector<TraceLevel>& levels) {
  std::vector<std::string> out;
  for (const std::string& path : sample_workloads())
    if (has_trace_header(path) && std::count(levels.begin(), levels.end(), header_level(path)))
      out.push_back(path);
  return out;
}

}  // namespace girtd
