#include "backends/backend.hpp"

#include <stdexcept>

#include "backends/golden_backend.hpp"
#include "backends/reference_backend.hpp"
#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"

namespace girtd {

void require_hardware_q(const Trace& trace) {
  for (const TraceFrame& f : trace.frames)
    if (!is_hardware_q(f.settings.q))
      throw InputError(trace.path, f.settings.q_line,
                       "Q must be 0 or a power of two 1/16..8 for the hardware back ends (Norm is a shift)");
}

std::vector<std::string> known_backends() { return {"reference", "golden", "approx", "rtl"}; }

std::unique_ptr<Backend> make_backend(const std::string& name, const Params& params) {
  if (name == "reference") return std::make_unique<ReferenceBackend>(EdgeRules{params.fill_top_left, params.edge_flags});
  if (name == "golden") return std::make_unique<GoldenBackend>(params);
  throw std::logic_error("not an untimed back end: " + name);  // CLI11 admits known_backends() only
}

}  // namespace girtd
