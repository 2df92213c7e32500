// For executables built without the traced back end (the check build):
// asking for a waveform is an internal error there.
#include <stdexcept>

#include "rtl/backend_rtl_core.hpp"

namespace girtd {

std::unique_ptr<BackendRtl> make_traced_backend_rtl(const Params&, uint32_t) {
  throw std::logic_error("this executable has no traced build of the back end");
}

}  // namespace girtd
