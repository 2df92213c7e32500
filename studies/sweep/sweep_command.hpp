// girtd sweep: a design-space sweep. Returns the process exit code (docs/interface.md):
// 0 success, 1 a check failed, 2 bad input or usage (InputError).
#pragma once

#include <string>
#include <vector>

#include "cli/config_loader.hpp"

namespace girtd {

struct SweepArgs {
  std::string spec;
  int jobs = 0;          // 0: every core
  std::string out_dir;   // default out/sweep/<spec name>
  bool slurm = false;    // the rows as a Slurm job array (planned here, submitted by the driver)
  std::string slice;     // "I/S": only rows I, I + S, ... (a Slurm array task); no tables
};

int run_sweep(const SweepArgs& a);
// `girtd --plan sweep ...`: the points' synthesis requests and RTL variants,
// the Slurm array (with --slurm), then "plots DIR".
std::vector<std::string> plan_sweep(const SweepArgs& a);

}  // namespace girtd
