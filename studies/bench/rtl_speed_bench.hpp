// The rtl back end's speed (`girtd bench --speed`): DDA clocks per wall
// second of `render --backend rtl` (report.json's dda_cycles over wall_s,
// median of 5, each in its own process) on cube.off, the demo scene and
// demo.trace, against the ceiling: the Verilated DDA alone (regress
// --dda-only's harness, no FIFO, HAD or VRAM) on the same parameter sets,
// dumped from a golden render.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "cli/config_loader.hpp"
#include "config/params.hpp"

namespace girtd {

struct RtlSpeedBench {
  std::string markdown;
  nlohmann::json rows = nlohmann::json::array();
  int failures = 0;  // a render failed
};

RtlSpeedBench run_rtl_speed_bench(const Params& params, const ConfigFiles& config, const std::string& out_dir);

}  // namespace girtd
