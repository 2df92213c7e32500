#include "rtl/backend_rtl.hpp"

#include <stdexcept>

#include "Vgirtd_backend.h"
#include "Vgirtd_backend__Syms.h"
#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"
#include "girtd/built_rtl.hpp"
#include "rtl/port_access.hpp"
#include "verilated.h"

namespace girtd {

struct BackendRtl::Impl {
  const Params& params;
  VerilatedContext ctx;
  std::unique_ptr<Vgirtd_backend> top;
  uint64_t ticks = 0;
  std::array<uint64_t, 8> state_clocks{};
  Impl(const Params& p, uint32_t x_seed) : params(p) {
    if (x_seed != 0) {
      ctx.randReset(2);
      ctx.randSeed(static_cast<int>(x_seed));
    }
    top = std::make_unique<Vgirtd_backend>(&ctx);
  }
  const VlUnpacked<QData, 1048576>& vram() const { return top->rootp->vlSymsp->TOP__girtd_backend__u_vram.mem; }
};

BackendRtl::BackendRtl(const Params& p, uint32_t x_seed) : impl_(std::make_unique<Impl>(p, x_seed)) {
  // Values fixed when the RTL was verilated (build/generated/hw/girtd_pkg.sv).
  if (p.fifo_max_depth != kBuiltFifoDepth || p.fifo_dda_had_depth > kBuiltFifoDepth)
    throw InputError("--config", 0, "fifo.max_depth / dda_had_depth: the RTL FIFO is built " +
                                        std::to_string(kBuiltFifoDepth) + " deep (change config/girtd.json and rebuild)");
  require_built_output_latency(p);
  Vgirtd_backend& t = *impl_->top;
  t.dda_period_ticks_i = static_cast<uint8_t>(p.ticks(p.dda_clock_ns));
  t.had_access_ticks_i = static_cast<uint16_t>(p.ticks(p.had_access_ns));
  t.had_blend_ticks_i = static_cast<uint16_t>(p.ticks(p.had_blend_extra_ns));
  t.vram_cycle_ticks_i = static_cast<uint16_t>(p.ticks(p.vram_cycle_ns));
  t.clear_ticks_i = static_cast<uint32_t>(p.vram_serial_transfers * (p.ticks(p.vram_serial_ns) + p.ticks(p.vram_cycle_ns)));
  t.vram_steal_period_ticks_i = static_cast<uint32_t>(p.ticks(p.vram_steal_every_ns));
  t.fifo_limit_i = static_cast<uint8_t>(p.fifo_dda_had_depth);
  t.write_behind_i = p.had_write_behind;
  t.prefetch_i = p.had_prefetch;
  t.dirty_bits_i = p.had_dirty_bits;
  t.one_minus_exact_i = p.one_minus_nf == OneMinusNf::kExact;
  t.walk_fix_i = p.walk_fix;
  t.pipelined_compare_i = p.xy_compare_pipelined;
  t.in_valid_i = 0;
  t.clear_i = t.flush_i = t.swap_i = 0;
  t.rst_ni = 0;
  for (int i = 0; i < 4; ++i) tick();
  t.rst_ni = 1;
  impl_->ticks = 0;
  impl_->state_clocks.fill(0);
}

BackendRtl::~BackendRtl() { impl_->top->final(); }

void BackendRtl::tick() {
  Vgirtd_backend& t = *impl_->top;
  t.clk_i = 0;
  t.eval();
  if (t.dda_active_o) ++impl_->state_clocks[t.dda_state_o & 7];
  t.clk_i = 1;
  t.eval();
  ++impl_->ticks;
}

void BackendRtl::drain() {
  Vgirtd_backend& t = *impl_->top;
  for (uint64_t guard = 0;; ++guard) {
    t.clk_i = 0;
    t.eval();
    if (t.idle_o) return;
    if (guard > (uint64_t{1} << 28)) throw std::logic_error("RTL back end did not go idle within 2^28 ticks (a deadlock)");
    tick();
  }
}

void BackendRtl::step_until_ready() {
  Vgirtd_backend& t = *impl_->top;
  t.in_valid_i = 0;
  for (uint64_t guard = 0;; ++guard) {
    t.clk_i = 0;
    t.eval();
    if (t.in_ready_o) return;
    if (guard > (uint64_t{1} << 28)) throw std::logic_error("RTL DDA did not become ready within 2^28 ticks");
    tick();
  }
}

void BackendRtl::step_to(uint64_t target) {
  impl_->top->in_valid_i = 0;
  while (impl_->ticks < target) tick();
}

uint64_t BackendRtl::ticks() const { return impl_->ticks; }

void BackendRtl::begin_frame(Rgb bg) {
  Vgirtd_backend& t = *impl_->top;
  drain();
  t.background_i = (uint32_t(bg.r) << 16) | (uint32_t(bg.g) << 8) | bg.b;
  t.clear_i = 1;
  tick();
  t.clear_i = 0;
  drain();
}

void BackendRtl::draw(const DdaParams& d) {
  Vgirtd_backend& t = *impl_->top;
  load_dda_ports(t, d, impl_->params);
  t.in_valid_i = 1;
  for (uint64_t guard = 0;; ++guard) {
    t.clk_i = 0;
    t.eval();
    const bool taken = t.in_ready_o;  // ready only on a DDA clock: the load happens at this edge
    tick();
    if (taken) break;
    if (guard > (uint64_t{1} << 28)) throw std::logic_error("RTL DDA did not take a parameter set within 2^28 ticks");
  }
  t.in_valid_i = 0;
}

void BackendRtl::end_frame() {
  Vgirtd_backend& t = *impl_->top;
  drain();
  t.flush_i = 1;
  tick();
  t.flush_i = 0;
  tick();
  drain();
  t.swap_i = 1;
  tick();
  t.swap_i = 0;
}

BackendCounters BackendRtl::counters() const {
  const Vgirtd_backend& t = *impl_->top;
  BackendCounters c;
  c.ticks = impl_->ticks;
  c.dda_clocks = t.dda_clocks_o;
  c.dda_wait_ticks = t.dda_wait_ticks_o;
  c.pixels_generated = t.pixels_generated_o;
  c.written = t.written_o;
  c.blended = t.blended_o;
  c.z_rejected = t.z_rejected_o;
  c.dropped = t.dropped_o;
  c.page_misses = t.page_misses_o;
  c.had_busy_ticks = t.had_busy_ticks_o;
  c.had_vram_wait_ticks = t.had_vram_wait_ticks_o;
  c.fifo_max = t.fifo_max_o;
  c.dda_state_clocks = impl_->state_clocks;
  return c;
}

std::vector<uint8_t> BackendRtl::shown_rgb() const {
  const auto& mem = impl_->vram();
  const bool front = impl_->top->front_o;  // 0: bits 63:40 are shown
  std::vector<uint8_t> out((size_t{1} << 20) * 3);
  for (size_t a = 0; a < (size_t{1} << 20); ++a) {
    const uint64_t w = mem[a];
    const uint32_t rgb = static_cast<uint32_t>((front ? (w >> 16) : (w >> 40)) & 0xFFFFFF);
    out[3 * a] = static_cast<uint8_t>(rgb >> 16);
    out[3 * a + 1] = static_cast<uint8_t>(rgb >> 8);
    out[3 * a + 2] = static_cast<uint8_t>(rgb);
  }
  return out;
}

std::vector<uint16_t> BackendRtl::z_plane() const {
  const auto& mem = impl_->vram();
  std::vector<uint16_t> out(size_t{1} << 20);
  for (size_t a = 0; a < out.size(); ++a) out[a] = static_cast<uint16_t>(mem[a] & 0xFFFF);
  return out;
}

}  // namespace girtd
