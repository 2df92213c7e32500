#include "backends/reference_backend.hpp"

#include <stdexcept>

#include "common/input_error.hpp"
#include "reference/reference_rasterizer.hpp"

namespace girtd {

void ReferenceBackend::begin(const FrameSource& input) {
  if (input.level() != TraceLevel::kTriangle && input.level() != TraceLevel::kPolygon)
    throw InputError(input.path(), 0,
                     "the reference back end needs triangle- or polygon-level input (a DDA trace holds no float triangles)");
}

void ReferenceBackend::draw(const Triangle& t) {
  ++triangles_in_;
  const bool drawn = rasterize_reference(t, frame_, rules_, [&](const ReferenceSample& s) {
    ++pixels_;
    had_.update(quantize_reference(s), s.layer, s.covered);
  });
  triangles_drawn_ += drawn;
}

void ReferenceBackend::draw(const DdaParams&) {
  throw std::logic_error("the reference back end draws triangles, not DDA parameter sets");
}

void ReferenceBackend::finish(RunStats& stats) const {
  stats.triangles_in = triangles_in_;
  stats.triangles_drawn = triangles_drawn_;
  stats.pixels_generated = pixels_;
  stats.had = had_.counts();
  stats.stages.push_back(untimed_stage("reference_raster", triangles_drawn_));
  stats.stages.push_back(untimed_stage("had", pixels_));
}

}  // namespace girtd
