// The simulator's own subcommands, render and regress (the campaigns are
// in studies/). Each returns the process exit code (docs/interface.md):
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
  std::string camera;  // --camera: a model file's camera by name
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
  int repeat = 1;  // a one-frame input drawn this many times (sustained rates)
};

int run_render(const RenderArgs& a);

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

}  // namespace girtd
