// The back end's traced build (FST compiled in), for --wave only.
#include "Vgirtd_backend_traced.h"
#include "Vgirtd_backend_traced__Syms.h"
#include "rtl/backend_rtl_core.hpp"
#include "verilated_fst_c.h"

namespace girtd {

std::unique_ptr<BackendRtl> make_traced_backend_rtl(const Params& p, uint32_t x_seed) {
  return std::make_unique<BackendRtlCore<Vgirtd_backend_traced>>(p, x_seed);
}

}  // namespace girtd
