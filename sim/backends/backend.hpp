// An untimed back end draws the primitives of one frame into the HAD. The
// registry (engine/backend_registry.hpp) makes one; the render session
// around it is shared.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backends/prune_plan.hpp"
#include "backends/run_stats.hpp"
#include "config/params.hpp"
#include "had/had.hpp"
#include "io/trace.hpp"

namespace girtd {

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  // Before the first frame: throws InputError for input this back end cannot
  // take, and sets itself up for the trace's level.
  virtual void begin(const Trace& trace) = 0;
  virtual void draw_frame(const TraceFrame& frame, Had& had, RunStats& stats) = 0;
  // Per-stage rows for the report, after the last frame.
  virtual void finish(RunStats& stats) const = 0;
  // --dump dda: hands every DDA parameter set the back end draws to `tap`;
  // false for a back end without a DDA.
  virtual bool tap_dda(std::function<void(const DdaParams&)> tap) {
    (void)tap;
    return false;
  }
  // What the simulator may leave out (backends/prune_plan.hpp), before begin().
  virtual void prune(const PrunePlan& plan) { (void)plan; }
};

// The hardware's Norm is a shift: every frame's Q must be 0 or a power of
// two 1/16..8 (InputError at the line that set it).
void require_hardware_q(const Trace& trace);

}  // namespace girtd
