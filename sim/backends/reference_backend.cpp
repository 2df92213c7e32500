#include "backends/reference_backend.hpp"

#include "common/input_error.hpp"
#include "reference/reference_rasterizer.hpp"

namespace girtd {

void ReferenceBackend::begin(const Trace& trace) {
  if (trace.level != TraceLevel::kTriangle)
    throw InputError(trace.path, 0,
                     "the reference back end needs triangle-level input (a DDA trace holds no float triangles)");
}

void ReferenceBackend::draw_frame(const TraceFrame& frame, Had& had, RunStats& stats) {
  for (const Triangle& t : frame.triangles) {
    ++stats.triangles_in;
    const bool drawn = rasterize_reference(t, frame.settings, rules_, [&](const ReferenceSample& s) {
      ++stats.pixels_generated;
      had.update(quantize_reference(s), s.layer, s.covered);
    });
    stats.triangles_drawn += drawn;
  }
}

void ReferenceBackend::finish(RunStats& stats) const {
  stats.stages.push_back(untimed_stage("reference_raster", stats.triangles_drawn));
  stats.stages.push_back(untimed_stage("had", stats.pixels_generated));
}

}  // namespace girtd
