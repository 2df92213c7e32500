// GIRTD's pipeline (docs/design.md §2) as a SystemC simulation: one module per
// stage, a FIFO of pipeline.fifo_depth items between each pair, the back end
// (approx or rtl) last. What enters depends on the input's level: polygons
// start at lighting, triangles at the window clip, DDA parameter sets at the
// back end. One simulation per process (SystemC elaborates once).
#pragma once

#include <string>

#include "backends/backend_entry.hpp"
#include "backends/render_session.hpp"
#include "config/params.hpp"
#include "io/frame_source.hpp"

namespace girtd {

// `input`: polygon level (models, scenes; the pipeline runs the front end
// itself), triangle or DDA level; its frames are taken as the run reaches them.
// `backend`: a timed entry (engine/backend_registry.hpp).
RenderOutput run_pipeline(const BackendEntry& backend, FrameSource& input, const Params& p, const RenderOptions& opt);

}  // namespace girtd
