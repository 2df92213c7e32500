// girtd bench, leaving out what a scene does not need:
// - culling (the modeled hardware): every sample scene on approx in the
//   thesis' design, with culling.objects, and with config/presets/culling.json:
//   objects and polygons removed, modeled time and rate, whether the frame
//   stayed the same and how many pixels changed;
// - pruning (the simulator): every sample input on approx with and without
//   --no-prune, wall time median of five each (runs alternate, each in its
//   own process), and their ratio.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "cli/config_loader.hpp"

namespace girtd {

struct LeaveOutBench {
  std::string markdown;
  nlohmann::json culling = nlohmann::json::array();
  nlohmann::json pruning = nlohmann::json::array();
  nlohmann::json pruning_ceiling;  // the most leaving out the out-of-view objects could save (both runs --no-prune)
  int failures = 0;  // a render that failed, or pruning that changed an output
};

LeaveOutBench run_leave_out_bench(const ConfigFiles& config, const std::string& out_dir);

}  // namespace girtd
