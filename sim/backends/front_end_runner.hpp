// Glue between the polygon level and the triangle level for the untimed back
// ends (golden, reference): one FrontEnd (models/frontend) over a run's
// frames, a frame at a time, and its counts. The timed back ends run the
// front end as SystemC stages instead (sim/pipeline). Either way a render
// runs it once: front_end_passes() counts the runs in this process
// (report.json `frontend_passes`).
#pragma once

#include <cstdint>
#include <vector>

#include "backends/prune_plan.hpp"
#include "config/params.hpp"
#include "frontend/front_end.hpp"
#include "frontend/frontend_counts.hpp"
#include "io/trace.hpp"

namespace girtd {

// The front end's options: the configuration's culling (modeled hardware)
// and the plan's pruning (the simulator).
FrontEndOptions front_end_options(const Params& params, const PrunePlan& plan);

class FrontEndRunner {
 public:
  // Counts one pass.
  FrontEndRunner(const Params& params, const PrunePlan& prune);
  // The frame's triangles, in drawing order.
  std::vector<Triangle> run(const WorldFrame& world, const FrameSettings& settings) {
    return fe_.run_frame(world, settings.window, settings.q);
  }
  // The same, the frame's polygons freed as soon as the front end is through
  // with them (before the sort).
  std::vector<Triangle> run_releasing(WorldFrame& world, const FrameSettings& settings) {
    return fe_.run_frame_releasing(world, settings.window, settings.q);
  }
  FrontendCounts counts() const { return fe_.counts(); }
  // A progress line over a frame's polygons (a one-frame run).
  void show_progress();

 private:
  FrontEnd fe_;
};

struct FrontEndRun {
  Trace triangles;        // level triangle, one frame per input frame (possibly empty)
  FrontendCounts counts;  // summed over the frames
};

// Every frame of a polygon-level trace at once (the stress campaign, tests).
FrontEndRun run_front_end(const Trace& polygons, const Params& params, const PrunePlan& prune);

// Runs of the front end over an input in this process: a FrontEndRunner and
// the pipeline's front-end stages each add one.
uint64_t front_end_passes();
void count_front_end_pass();

}  // namespace girtd
