// girtd bench, the SystemC pipeline's table: every sample input (traces,
// directed traces, models, scenes; not the thesis-level ones) rendered on
// golden, approx and rtl, each in its own process (SystemC elaborates once
// per process). Checks that the three frames are the same, that approx and
// rtl count the same pixels and DDA states, and that approx's modeled time
// is rtl's to the base tick; measures the
// speed ratio, the rtl's DDA clocks per wall second and, on triangle
// traces, the cost of the SystemC coupling against the bare Verilated
// harness (rtl/timing_comparison).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/config_loader.hpp"
#include "config/params.hpp"

namespace girtd {

struct PipelineBench {
  std::string markdown;
  nlohmann::json rows = nlohmann::json::array();
  int failures = 0;
};

// `config`: the --config files passed on to every render. Compares every
// render with the stored expectations (cli/expectations.hpp) blessed under
// the same configuration; `bless` rewrites them instead (not when back ends
// disagree).
PipelineBench run_pipeline_bench(const Params& params, const ConfigFiles& config, const std::string& out_dir,
                                 bool bless = false, const std::vector<std::string>& inputs = {});

// The same table under each memory-side option alone and all together
// (write-behind, prefetch, dirty bits, stolen VRAM cycles): `bench
// --pipeline --options`. Rows carry `options`, the set's name. Default
// inputs: traces/accuracy_inputs.txt (each of 100,000 pixels or more).
PipelineBench run_option_matrix_bench(const ConfigFiles& config, const std::string& out_dir,
                                      const std::vector<std::string>& inputs = {});

// The cost of the coupling and of the waveform ability, on the demo trace:
// rtl in the pipeline, the bare Verilated harness, the pipeline keeping step
// every tick, the traced build with almost nothing to dump, a 100 us window
// (wall time per simulated tick, best of three, each render in its own process).
struct WaveCostBench {
  std::string markdown;
  nlohmann::json rows = nlohmann::json::array();
};
WaveCostBench run_wave_cost_bench(const Params& params, const ConfigFiles& config, const std::string& out_dir);

}  // namespace girtd
