// One back end, whichever it is (reference, golden, approx, rtl): the
// registry (engine/backend_registry.hpp) makes it, a run drives it frame by
// frame (begin_frame, draw, end_frame) and reads the picture. A back end
// that models time answers the timing questions through modeled_time(); an
// untimed one answers nullptr: not modeled.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "backends/modeled_time.hpp"
#include "backends/prune_plan.hpp"
#include "backends/run_stats.hpp"
#include "common/types.hpp"
#include "dda/dda_params.hpp"
#include "io/png_io.hpp"
#include "io/frame_source.hpp"

namespace girtd {

class Backend {
 public:
  virtual ~Backend() = default;
  // Before the first frame (no frame taken yet): throws InputError for input
  // this back end cannot take, and sets itself up for its level. Polygon
  // input reaches it as the front end's triangles.
  virtual void begin(const FrameSource& input) = 0;
  // What the simulator may leave out (backends/prune_plan.hpp), before begin().
  virtual void prune(const PrunePlan& plan) { (void)plan; }
  // --dump dda: hands every DDA parameter set the back end draws to `tap`
  // (an empty one ends it); false for a back end without a DDA.
  virtual bool tap_dda(std::function<void(const DdaParams&)> tap) {
    (void)tap;
    return false;
  }

  virtual void begin_frame(const FrameSettings& s) = 0;  // the clear
  // A triangle of the front end's (a back end that prepares its own), or a
  // DDA parameter set (the preparer's output).
  virtual void draw(const Triangle& t);
  virtual void draw(const DdaParams& d) = 0;
  virtual void end_frame() = 0;  // the swap (a timed back end drains and writes the cache back first)
  virtual RgbImage shown() const = 0;
  virtual std::vector<uint16_t> z_plane() const = 0;
  // What it counted, after the last frame (a timed back end's counts are
  // read through modeled_time() by the pipeline that timed it).
  virtual void finish(RunStats& stats) const { (void)stats; }

  // Modeled time: nullptr where it is not modeled.
  virtual ModeledTime* modeled_time() { return nullptr; }
};

// The hardware's Norm is a shift: every frame's Q must be 0 or a power of
// two 1/16..8 (InputError at the line that set it).
void require_hardware_q(const FrameSource& input);
// What the pipeline's back ends take: that Q, and no thesis-level trace (it
// runs the appendix program, which only an untimed back end has).
void require_pipeline_input(const FrameSource& input);

}  // namespace girtd
