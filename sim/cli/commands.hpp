// The girtd subcommands. Each returns the process exit code (docs/interface.md):
// 0 success, 1 a check failed, 2 bad input or usage (InputError).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/config_loader.hpp"

namespace girtd {

struct RenderArgs {
  std::string input;
  std::string backend = "golden";
  std::string out_dir;  // default out/<input stem>
  std::string level;
  std::string frames = "last";
  std::string wave, wave_window;
  std::vector<std::string> wave_scopes;
  std::optional<double> aa;
  std::string dump;  // LEVEL=FILE
  ConfigFiles config;
  bool z_png = false;
  bool quiet = false;
  bool no_prune = false;
  std::optional<double> sample_timing;
  std::string compare;  // "reference": report.html gains the error against the reference back end
  int repeat = 1;  // a one-frame input drawn this many times (sustained rates)  // approx: sampled timing (the accuracy command's estimator)
};

int run_render(const RenderArgs& a);
// campaign_only: the rows read from the study campaign's stored results.
int run_claims(const ConfigFiles& config, bool campaign_only = false);
struct BenchArgs {
  ConfigFiles config;
  std::string out = "out/bench";
  bool pipeline_only = false, leave_out_only = false, speed_only = false;
  bool bless = false;          // rewrite the stored expectations from this run (cli/expectations.hpp)
  bool option_matrix = false;  // the pipeline table under each memory-side option
  std::vector<std::string> inputs;  // the pipeline table's (default: the sample workloads)
};
int run_bench(const BenchArgs& a);
struct RegressArgs {
  std::vector<std::string> traces;  // empty: every trace under traces/
  int random = 0;                   // extra random triangles
  uint32_t seed = 1;
  double stall = 0.3;               // back-pressure probability on every other triangle
  bool both_compare_modes = false;  // run ECL and TTL sequencing
  bool dda_only = false;            // skip the whole-back-end RTL (FIFO, HAD, cache, VRAM)
  ConfigFiles config;
};

int run_regress(const RegressArgs& a);

struct StressArgs {
  std::vector<std::string> families;  // empty: every family
  ConfigFiles config;
  std::string out_dir = "out/stress";
  bool fast = false;         // the CTest subset of each family
  double timeout_s = 300;    // a render that takes longer is a hang
};

int run_stress(const StressArgs& a);

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
