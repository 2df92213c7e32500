// The driver of the Verilated back end, for any build of girtd_backend (the
// fast one, or the one with FST tracing compiled in: same ports, different
// class). backend_rtl.cpp and backend_rtl_traced.cpp instantiate it.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "common/input_error.hpp"
#include "girtd/built_rtl.hpp"
#include "rtl/backend_rtl.hpp"
#include "rtl/port_access.hpp"
#include "verilated.h"

class VerilatedFstC;

namespace girtd {

// What BackendRtl forwards to: one per Verilated build.
class BackendRtlDriver {
 public:
  virtual ~BackendRtlDriver() = default;
  virtual void begin_frame(Rgb background) = 0;
  virtual void draw(const DdaParams& d) = 0;
  virtual void end_frame() = 0;
  virtual void drain() = 0;
  virtual void step_until_ready() = 0;
  virtual void step_to(uint64_t tick) = 0;
  virtual uint64_t ticks() const = 0;
  virtual BackendCounters counters() const = 0;
  virtual std::vector<uint8_t> shown_rgb() const = 0;
  virtual std::vector<uint16_t> z_plane() const = 0;
  virtual void on_tick(std::function<void(const BackendRtl::TickProbe&)> hook) = 0;
  // Records the model's signals into `tfp` (the traced build only).
  virtual void trace(VerilatedFstC* tfp) = 0;
};

template <typename M, typename = void>
struct HasFstTrace : std::false_type {};
template <typename M>
struct HasFstTrace<M, std::void_t<decltype(std::declval<M&>().trace(std::declval<VerilatedFstC*>(), 0))>>
    : std::true_type {};

template <typename Model>
class BackendRtlCore final : public BackendRtlDriver {
 public:
  BackendRtlCore(const Params& p, uint32_t x_seed) : params_(p) {
    if (x_seed != 0) {
      ctx_.randReset(2);
      ctx_.randSeed(static_cast<int>(x_seed));
    }
    if constexpr (HasFstTrace<Model>::value) ctx_.traceEverOn(true);
    top_ = std::make_unique<Model>(&ctx_, "TOP");
    // Values fixed when the RTL was verilated (build/generated/hw/girtd_pkg.sv).
    if (p.fifo_max_depth != kBuiltFifoDepth || p.fifo_dda_had_depth > kBuiltFifoDepth)
      throw InputError("--config", 0, "fifo.max_depth / dda_had_depth: the RTL FIFO is built " +
                                          std::to_string(kBuiltFifoDepth) + " deep (change config/girtd.json and rebuild)");
    require_built_output_latency(p);
    Model& t = *top_;
    t.dda_period_ticks_i = static_cast<uint8_t>(p.ticks(p.dda_clock_ns));
    t.had_access_ticks_i = static_cast<uint16_t>(p.ticks(p.had_access_ns));
    t.had_blend_ticks_i = static_cast<uint16_t>(p.ticks(p.had_blend_extra_ns));
    t.vram_cycle_ticks_i = static_cast<uint16_t>(p.ticks(p.vram_cycle_ns));
    t.clear_ticks_i =
        static_cast<uint32_t>(p.vram_serial_transfers * (p.ticks(p.vram_serial_ns) + p.ticks(p.vram_cycle_ns)));
    t.vram_steal_period_ticks_i = static_cast<uint32_t>(p.ticks(p.vram_steal_every_ns));
    period_ = static_cast<uint64_t>(p.ticks(p.dda_clock_ns));
    steal_period_ = static_cast<uint64_t>(p.ticks(p.vram_steal_every_ns));
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
    ticks_ = 0;
    state_clocks_.fill(0);
  }
  ~BackendRtlCore() override { top_->final(); }

  void begin_frame(Rgb bg) override {
    Model& t = *top_;
    drain();
    t.background_i = (uint32_t(bg.r) << 16) | (uint32_t(bg.g) << 8) | bg.b;
    t.clear_i = 1;
    tick();
    t.clear_i = 0;
    drain();
  }

  void draw(const DdaParams& d) override {
    Model& t = *top_;
    load_dda_ports(t, d, params_);
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

  void end_frame() override {
    Model& t = *top_;
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

  void drain() override {
    clock_until([](const Model& t) { return bool(t.idle_o); }, "the RTL back end did not go idle");
  }

  void step_until_ready() override {
    top_->in_valid_i = 0;
    clock_until([](const Model& t) { return bool(t.in_ready_o); }, "the RTL DDA did not become ready");
  }

  // Clocks with no input up to `target`. A back end that is idle (DDA,
  // FIFO, HAD and VRAM) on a DDA clock stays so, and nothing in it counts:
  // whole DDA periods are skipped without clocking (the clock-enable phase
  // is unchanged by a multiple of its period). Not with stolen VRAM cycles
  // (a free-running counter) or a tick hook (waveforms) attached.
  void step_to(uint64_t target) override {
    Model& t = *top_;
    t.in_valid_i = 0;
    const bool may_skip = !on_tick_ && steal_period_ == 0;
    while (ticks_ < target) {
      if (may_skip && target - ticks_ >= period_) {
        t.clk_i = 0;
        t.eval();
        if (t.idle_o) {
          ticks_ += (target - ticks_) / period_ * period_;
          continue;
        }
      }
      tick();
    }
  }

  uint64_t ticks() const override { return ticks_; }

  BackendCounters counters() const override {
    const Model& t = *top_;
    BackendCounters c;
    c.ticks = ticks_;
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
    c.dda_state_clocks = state_clocks_;
    return c;
  }

  std::vector<uint8_t> shown_rgb() const override {
    const auto& mem = vram();
    const bool front = top_->front_o;  // 0: bits 63:40 are shown
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

  std::vector<uint16_t> z_plane() const override {
    const auto& mem = vram();
    std::vector<uint16_t> out(size_t{1} << 20);
    for (size_t a = 0; a < out.size(); ++a) out[a] = static_cast<uint16_t>(mem[a] & 0xFFFF);
    return out;
  }

  void on_tick(std::function<void(const BackendRtl::TickProbe&)> hook) override { on_tick_ = std::move(hook); }
  void trace(VerilatedFstC* tfp) override {
    if constexpr (HasFstTrace<Model>::value) top_->trace(tfp, 99);
    else throw std::logic_error("this Verilated build of the back end has no tracing");
  }

 private:
  // Clocks until `done` holds with the clock low (before the next edge).
  template <typename Done>
  void clock_until(Done done, const char* what) {
    Model& t = *top_;
    for (uint64_t guard = 0;; ++guard) {
      t.clk_i = 0;
      t.eval();
      if (done(t)) return;
      if (guard > (uint64_t{1} << 28)) throw std::logic_error(std::string(what) + " within 2^28 ticks (a deadlock)");
      tick();
    }
  }

  void tick() {
    Model& t = *top_;
    t.clk_i = 0;
    t.eval();
    if (t.dda_active_o) ++state_clocks_[t.dda_state_o & 7];
    BackendRtl::TickProbe probe{};
    if (on_tick_) {
      probe = {ticks_ + 1, false, bool(t.pixel_push_o), int(t.pixel_x_o), int(t.pixel_y_o)};
      on_tick_(probe);
    }
    t.clk_i = 1;
    t.eval();
    ++ticks_;
    if (on_tick_) {
      probe.rising = true;
      on_tick_(probe);
    }
  }
  const auto& vram() const { return top_->rootp->vlSymsp->TOP__girtd_backend__u_vram.mem; }

  const Params& params_;
  VerilatedContext ctx_;
  std::unique_ptr<Model> top_;
  uint64_t ticks_ = 0;
  uint64_t period_ = 1, steal_period_ = 0;  // DDA clock and VRAM steal period, in ticks
  std::array<uint64_t, 8> state_clocks_{};
  std::function<void(const BackendRtl::TickProbe&)> on_tick_;
};

}  // namespace girtd
