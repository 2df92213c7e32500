// girtd stress: generated extreme cases on reference, golden and rtl. Returns the process exit code (docs/interface.md):
// 0 success, 1 a check failed, 2 bad input or usage (InputError).
#pragma once

#include <string>
#include <vector>

#include "cli/config_loader.hpp"

namespace girtd {

struct StressArgs {
  std::vector<std::string> families;  // empty: every family
  ConfigFiles config;
  std::string out_dir = "out/stress";
  bool fast = false;         // the CTest subset of each family
  double timeout_s = 300;    // a render that takes longer is a hang
};

int run_stress(const StressArgs& a);

}  // namespace girtd
