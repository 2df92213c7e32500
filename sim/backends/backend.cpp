#include "backends/backend.hpp"

#include <stdexcept>

#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"

namespace girtd {

void Backend::draw(const Triangle&) {
  throw std::logic_error("this back end draws DDA parameter sets: the preparer runs before it");
}

void require_hardware_q(const Trace& trace) {
  for (const TraceFrame& f : trace.frames)
    if (!is_hardware_q(f.settings.q))
      throw InputError(trace.path, f.settings.q_line,
                       "Q must be 0 or a power of two 1/16..8 for the hardware back ends (Norm is a shift)");
}

void require_pipeline_input(const Trace& trace) {
  if (trace.level == TraceLevel::kThesis)
    throw InputError(trace.path, 0, "a thesis-level trace runs the appendix program: use --backend golden");
  require_hardware_q(trace);
}

}  // namespace girtd
