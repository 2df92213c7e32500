#include "backends/backend.hpp"

#include <stdexcept>

#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"

namespace girtd {

void Backend::draw(const Triangle&) {
  throw std::logic_error("this back end draws DDA parameter sets: the preparer runs before it");
}

void require_hardware_q(const FrameSource& input) {
  for (const FrameSettings& s : input.settings())
    if (!is_hardware_q(s.q))
      throw InputError(input.path(), s.q_line,
                       "Q must be 0 or a power of two 1/16..8 for the hardware back ends (Norm is a shift)");
}

void require_pipeline_input(const FrameSource& input) {
  if (input.level() == TraceLevel::kThesis)
    throw InputError(input.path(), 0, "a thesis-level trace runs the appendix program: use --backend golden");
  require_hardware_q(input);
}

}  // namespace girtd
