// The timing questions a back end that models time answers (Backend::
// modeled_time(), backends/backend.hpp), in base ticks of the DDA, FIFO,
// HAD, cache and VRAM: approx (golden DDA and HAD for what is drawn, the
// timing model of sim/dda and sim/had for when) and rtl (the Verilated
// girtd_backend, clocked tick by tick). The SystemC back-end stage
// (pipeline/backend_stage.hpp) asks them as parameter sets arrive.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/types.hpp"
#include "config/params.hpp"
#include "dda/dda_engine.hpp"
#include "fifo/fifo_levels.hpp"
#include "backends/screen_maps.hpp"
#include "backends/sampled_timing.hpp"
#include "had/had.hpp"

namespace girtd {

class BackendRtl;

struct BackendResult {
  uint64_t ticks = 0;             // base ticks from the first frame's clear to the last swap
  uint64_t triangles_drawn = 0;
  uint64_t pixels_generated = 0;
  HadCounts had;
  DdaRunStats dda;                // cycles, emitted, clocks per state
  uint64_t dda_wait_ticks = 0;    // DDA waiting on a full DDA -> HAD FIFO
  uint64_t page_misses = 0;
  uint64_t had_busy_ticks = 0;
  uint64_t had_vram_wait_ticks = 0;  // HAD waiting for a page (write-back and fetch)
  uint64_t fifo_max = 0;          // DDA -> HAD FIFO
  std::optional<SamplingStats> sampling;  // approx with sampled timing
};

// The counters a timeline reads often (cheap to read, unlike result()).
struct BackendCounters {
  uint64_t dda_clocks = 0, dda_wait_ticks = 0, had_busy_ticks = 0;
};

class ModeledTime {
 public:
  virtual ~ModeledTime() = default;
  // The tick the DDA can take the next parameter set (the rtl back end
  // clocks the RTL up to it).
  virtual uint64_t ready_tick() = 0;
  // Nothing arrived before `tick`: the back end runs on without input.
  virtual void idle_until(uint64_t tick) = 0;
  virtual void drain() = 0;  // until the DDA, FIFO and HAD are idle
  virtual uint64_t now_tick() const = 0;
  virtual BackendResult result() const = 0;
  virtual BackendCounters counters() const = 0;
  // Where on the screen it spent its effort (report.html's heat maps).
  virtual std::optional<ScreenMaps> screen_maps() const { return std::nullopt; }
  // The DDA -> HAD FIFO's largest count per bin of modeled time, up to `end` (a tick).
  virtual std::optional<FifoSeries> fifo_levels(uint64_t end) const {
    (void)end;
    return std::nullopt;
  }
  // Waveforms (the back end that runs the RTL): the RTL to record, and a call on every tick.
  virtual BackendRtl* rtl() { return nullptr; }
};

}  // namespace girtd
