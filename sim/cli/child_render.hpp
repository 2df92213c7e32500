// One `girtd render` in a child process (SystemC elaborates once per
// process), for the benches: its report.json, or null when it failed.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/config_loader.hpp"

namespace girtd {

// `log`: the child's stdout and stderr are appended there ("": to DIR.log,
// and a failure is reported on our stderr with that path);
// `exit_code`: the child's (-1: killed by a signal, or not started).
nlohmann::json render_in_child(const std::string& input, const std::string& backend, const std::string& dir,
                               const ConfigFiles& config, const std::vector<std::string>& extra = {},
                               const std::string& log = "", int* exit_code = nullptr);

// `runs` renders of the same input, each in its own process (the speed
// benches' medians): their wall_s, and the last report, null when one failed
// (the runs stop there).
struct RepeatedRender {
  std::vector<double> walls;
  nlohmann::json last;
};
RepeatedRender render_repeatedly(int runs, const std::string& input, const std::string& backend, const std::string& dir,
                                 const ConfigFiles& config);

}  // namespace girtd
