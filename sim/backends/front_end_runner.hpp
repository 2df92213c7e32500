// Glue between the polygon level and the triangle level for the untimed back
// ends (golden, reference): runs every frame of a polygon-level trace through
// one FrontEnd (models/frontend) and returns the triangle-level trace they
// draw, with the front end's counts. The timed back ends run the front end
// as SystemC stages instead (sim/pipeline). Either way a render runs it once:
// front_end_passes() counts the runs in this process (report.json
// `frontend_passes`).
#pragma once

#include <cstdint>

#include "backends/prune_plan.hpp"
#include "config/params.hpp"
#include "frontend/front_end_stages.hpp"
#include "frontend/frontend_counts.hpp"
#include "io/trace.hpp"

namespace girtd {

struct FrontEndRun {
  Trace triangles;        // level triangle, one frame per input frame (possibly empty)
  FrontendCounts counts;  // summed over the frames
};

FrontEndRun run_front_end(const Trace& polygons, const Params& params, const PrunePlan& prune);
// The same, each frame's polygons released once the front end is through
// with them (the frames' settings stay).
FrontEndRun run_front_end_releasing(Trace& polygons, const Params& params, const PrunePlan& prune);

// The front end's options: the configuration's culling (modeled hardware)
// and the plan's pruning (the simulator).
FrontEndOptions front_end_options(const Params& params, const PrunePlan& plan);

// Runs of the front end over an input in this process: run_front_end and the
// pipeline's front-end stages each add one.
uint64_t front_end_passes();
void count_front_end_pass();

}  // namespace girtd
