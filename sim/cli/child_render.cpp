#include "cli/child_render.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "io/subprocess.hpp"

namespace girtd {

nlohmann::json render_in_child(const std::string& input, const std::string& backend, const std::string& dir,
                               const ConfigFiles& config, const std::vector<std::string>& extra,
                               const std::string& log, int* exit_code) {
  std::vector<std::string> args = {self_executable(), "render", input, "--backend", backend, "--out", dir, "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  for (const std::string& a : config_args(config)) args.push_back(a);
  // Its warnings (a bench renders the same input many times) go to a log
  // beside its folder unless the caller keeps one; a failure says where.
  const std::string to = log.empty() ? dir + ".log" : log;
  std::error_code ignored;  // the child makes DIR; its log's folder must be there before it starts
  std::filesystem::create_directories(std::filesystem::path(to).parent_path(), ignored);
  const int rc = run_process_logged(args, to);
  if (exit_code) *exit_code = rc;
  if (rc != 0) {
    if (log.empty())
      std::fprintf(stderr, "girtd: the render of %s on %s failed (exit %d); its output: %s\n", input.c_str(),
                   backend.c_str(), rc, to.c_str());
    return nullptr;
  }
  std::ifstream in(dir + "/report.json");
  return nlohmann::json::parse(in);
}

RepeatedRender render_repeatedly(int runs, const std::string& input, const std::string& backend, const std::string& dir,
                                 const ConfigFiles& config) {
  RepeatedRender r;
  for (int i = 0; i < runs; ++i) {
    r.last = render_in_child(input, backend, dir, config);
    if (r.last.is_null()) break;
    r.walls.push_back(r.last.at("wall_s"));
  }
  return r;
}

}  // namespace girtd
