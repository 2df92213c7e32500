// girtd bench, the SystemC pipeline's table: every sample input (traces,
// directed traces, models, scenes; not the thesis-level ones) rendered on
// golden, approx and rtl, each in its own process (SystemC elaborates once
// per process). Checks that the three frames are the same, that approx and
// rtl count the same pixels and DDA states, and that approx's modeled time
// is within 2 % of rtl's on inputs of 100,000 pixels or more; measures the
// speed ratio, the rtl's DDA clocks per wall second and, on triangle
// traces, the cost of the SystemC coupling against the bare Verilated
// harness (rtl/timing_comparison).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "config/params.hpp"

namespace girtd {

struct PipelineBench {
  std::string markdown;
  nlohmann::json rows = nlohmann::json::array();
  int failures = 0;
};

// `config`: the --config file passed on to every render ("" for none).
PipelineBench run_pipeline_bench(const Params& params, const std::string& config, const std::string& out_dir);

// The cost of the waveform ability: the rtl back end on the demo trace
// without --wave, with the traced build but nothing to dump, and with a
// 100 us window (wall time, best of three, each in its own process).
struct WaveCostBench {
  std::string markdown;
  nlohmann::json rows = nlohmann::json::array();
};
WaveCostBench run_wave_cost_bench(const std::string& config, const std::string& out_dir);

}  // namespace girtd
