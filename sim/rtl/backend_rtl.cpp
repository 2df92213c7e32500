#include "rtl/backend_rtl.hpp"

#include "Vgirtd_backend.h"
#include "Vgirtd_backend__Syms.h"
#include "rtl/backend_rtl_core.hpp"

namespace girtd {

std::unique_ptr<BackendRtl> make_traced_backend_rtl(const Params& p, uint32_t x_seed);

std::unique_ptr<BackendRtl> make_backend_rtl(const Params& p, uint32_t x_seed, bool traced) {
  if (traced) return make_traced_backend_rtl(p, x_seed);
  return std::make_unique<BackendRtlCore<Vgirtd_backend>>(p, x_seed);
}

}  // namespace girtd
