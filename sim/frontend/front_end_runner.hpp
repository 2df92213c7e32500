// Glue between the polygon level and the triangle level: runs every frame of
// a polygon-level trace through one FrontEnd (models/frontend) and returns
// the triangle-level trace the back ends draw, with the front end's counts.
#pragma once

#include "config/params.hpp"
#include "frontend/frontend_counts.hpp"
#include "io/trace.hpp"

namespace girtd {

struct FrontEndRun {
  Trace triangles;        // level triangle, one frame per input frame (possibly empty)
  FrontendCounts counts;  // summed over the frames
};

FrontEndRun run_front_end(const Trace& polygons, const Params& params);

}  // namespace girtd
