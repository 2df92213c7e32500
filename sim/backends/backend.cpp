#include "backends/backend.hpp"

#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"

namespace girtd {

void require_hardware_q(const Trace& trace) {
  for (const TraceFrame& f : trace.frames)
    if (!is_hardware_q(f.settings.q))
      throw InputError(trace.path, f.settings.q_line,
                       "Q must be 0 or a power of two 1/16..8 for the hardware back ends (Norm is a shift)");
}

}  // namespace girtd
