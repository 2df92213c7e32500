// girtd bench: speed and error tables of the back ends. Returns the process exit code (docs/interface.md):
// 0 success, 1 a check failed, 2 bad input or usage (InputError).
#pragma once

#include <string>
#include <vector>

#include "cli/config_loader.hpp"

namespace girtd {

struct BenchArgs {
  ConfigFiles config;
  std::string out = "out/bench";
  bool pipeline_only = false, leave_out_only = false, speed_only = false;
  bool scale_only = false;          // the simulator's cost against the input's size (scale_bench.hpp)
  std::vector<long> scale_sizes;    // its meshes' triangle counts
  int scale_runs = 3;
  std::vector<long> animation_frames;  // its animation's short and long frame counts (animation_bench.hpp)
  bool bless = false;          // rewrite the stored expectations from this run (cli/expectations.hpp)
  bool option_matrix = false;  // the pipeline table under each memory-side option
  std::vector<std::string> inputs;  // the pipeline table's (default: the sample workloads)
};
int run_bench(const BenchArgs& a);

}  // namespace girtd
