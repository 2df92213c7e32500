// girtd accuracy: error against run time. Returns the process exit code (docs/interface.md):
// 0 success, 1 a check failed, 2 bad input or usage (InputError).
#pragma once

#include <string>
#include <vector>

#include "cli/config_loader.hpp"

namespace girtd {

struct AccuracyArgs {
  std::vector<std::string> inputs;  // empty: traces/accuracy_inputs.txt
  std::vector<std::string> levels;  // empty: accuracy/accuracy_levels.hpp's default
  std::vector<std::string> vary;    // KEY=V1,V2,...
  ConfigFiles config;
  std::string out_dir = "out/accuracy";
};

int run_accuracy(const AccuracyArgs& a);
// `girtd --plan accuracy ...`: the RTL variants its levels need, then "plots DIR".
std::vector<std::string> plan_accuracy(const AccuracyArgs& a);

}  // namespace girtd
