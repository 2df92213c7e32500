// The Verilated DDA (hw/dda) driven clock by clock from C++, without SystemC:
// load one parameter set, clock until it is done and its pixels drained.
// The same interface as the golden DdaEngine, so the two compare directly.
#pragma once

#include <cstdint>
#include <memory>
#include <random>

#include "config/params.hpp"
#include "dda/dda_engine.hpp"

namespace girtd {

struct DdaRtlOptions {
  double stall_probability = 0;  // chance per clock that the receiver refuses a pixel
  uint32_t seed = 1;
};

struct DdaRtlResult {
  DdaRunStats stats;          // counted DDA clocks (stalls excluded), emitted pixels, per state
  uint64_t stall_cycles = 0;  // clocks the DDA waited on a full output
};

class DdaRtl {
 public:
  // `x_seed` != 0 randomizes X/uninitialized state (meaningful in the check build).
  explicit DdaRtl(const Params& p, uint32_t x_seed = 0);
  ~DdaRtl();
  DdaRtl(const DdaRtl&) = delete;
  DdaRtl& operator=(const DdaRtl&) = delete;

  DdaRtlResult run(const DdaParams& in, const DdaEngine::PixelSink& sink, const DdaRtlOptions& opt = {});

  // Writes Verilator coverage (check build only; no-op otherwise).
  void write_coverage(const std::string& path) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace girtd
