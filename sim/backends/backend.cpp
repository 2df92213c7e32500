#include "backends/backend.hpp"

#include "backends/golden_backend.hpp"
#include "backends/reference_backend.hpp"
#include "common/input_error.hpp"

namespace girtd {

std::vector<std::string> known_backends() { return {"reference", "golden", "approx", "rtl"}; }

std::unique_ptr<Backend> make_backend(const std::string& name, const Params& params) {
  if (name == "reference") return std::make_unique<ReferenceBackend>();
  if (name == "golden") return std::make_unique<GoldenBackend>(params);
  if (name == "approx" || name == "rtl")
    throw InputError("--backend", 0, "the " + name + " back end is not built yet (available: reference, golden)");
  throw InputError("--backend", 0, "unknown back end '" + name + "' (reference, golden, approx, rtl)");
}

}  // namespace girtd
