// golden against Mesa's llvmpipe (`girtd bench --speed`; issue "Simulator
// speed": golden within 2x of single-threaded llvmpipe): 20,000 random
// opaque 200-pixel triangles (tools/make_opaque_trace.py, Q = 0, Z test),
// golden's report.json `wall_s` (each render in its own process) against
// llvmpipe's clear-to-glFinish time on the same triangles
// (studies/accuracy/llvmpipe_render.*), in pairs run in turn; the ratio is the
// median of the pairs'. Both count the triangles in memory to the final
// colour and Z buffers, the clear included.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "cli/config_loader.hpp"
#include "config/params.hpp"

namespace girtd {

struct GoldenSpeedBench {
  std::string markdown;
  nlohmann::json rows = nlohmann::json::array();
  int failures = 0;  // the workload, a render or llvmpipe failed
};

// The `girtd --plan` line asking the driver for the workload, a trace made
// by tools/make_opaque_trace.py under out_dir.
std::string golden_speed_bench_plan_line(const std::string& out_dir);

GoldenSpeedBench run_golden_speed_bench(const Params& params, const ConfigFiles& config, const std::string& out_dir);

}  // namespace girtd
