#include "cli/child_render.hpp"

#include <fstream>

#include "io/subprocess.hpp"

namespace girtd {

nlohmann::json render_in_child(const std::string& input, const std::string& backend, const std::string& dir,
                               const ConfigFiles& config, const std::vector<std::string>& extra,
                               const std::string& log, int* exit_code) {
  std::vector<std::string> args = {self_executable(), "render", input, "--backend", backend, "--out", dir, "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  for (const std::string& a : config_args(config)) args.push_back(a);
  const int rc = log.empty() ? run_process(args, false) : run_process_logged(args, log);
  if (exit_code) *exit_code = rc;
  if (rc != 0) return nullptr;
  std::ifstream in(dir + "/report.json");
  return nlohmann::json::parse(in);
}

}  // namespace girtd
