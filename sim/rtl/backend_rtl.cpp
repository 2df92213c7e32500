#include "rtl/backend_rtl.hpp"

#include "Vgirtd_backend.h"
#include "Vgirtd_backend__Syms.h"
#include "rtl/backend_rtl_core.hpp"

namespace girtd {

std::unique_ptr<BackendRtlDriver> make_traced_backend_driver(const Params& p, uint32_t x_seed);

BackendRtl::BackendRtl(const Params& p, uint32_t x_seed, bool traced)
    : impl_(traced ? make_traced_backend_driver(p, x_seed)
                   : std::unique_ptr<BackendRtlDriver>(std::make_unique<BackendRtlCore<Vgirtd_backend>>(p, x_seed))) {}

BackendRtl::~BackendRtl() = default;

void BackendRtl::begin_frame(Rgb background) { impl_->begin_frame(background); }
void BackendRtl::draw(const DdaParams& d) { impl_->draw(d); }
void BackendRtl::end_frame() { impl_->end_frame(); }
void BackendRtl::drain() { impl_->drain(); }
void BackendRtl::step_until_ready() { impl_->step_until_ready(); }
void BackendRtl::step_to(uint64_t tick) { impl_->step_to(tick); }
uint64_t BackendRtl::ticks() const { return impl_->ticks(); }
void BackendRtl::on_tick(std::function<void(const TickProbe&)> hook) { impl_->on_tick(std::move(hook)); }
void BackendRtl::trace(VerilatedFstC* tfp) { impl_->trace(tfp); }
BackendCounters BackendRtl::counters() const { return impl_->counters(); }
std::vector<uint8_t> BackendRtl::shown_rgb() const { return impl_->shown_rgb(); }
std::vector<uint16_t> BackendRtl::z_plane() const { return impl_->z_plane(); }

}  // namespace girtd
