// The rtl back end for any build of girtd_backend (the fast one, or the one
// with FST tracing compiled in: same ports, different class).
// backend_rtl.cpp and backend_rtl_traced.cpp instantiate it.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "timeline/series_switch.hpp"
#include "common/input_error.hpp"
#include "rtl/backend_rtl.hpp"
#include "layout/rtl_layout.hpp"
#include "dda/dda_port_access.hpp"
#include "rtl/rtl_screen_maps.hpp"
#include "verilated.h"

class VerilatedFstC;

namespace girtd {

template <typename M, typename = void>
struct HasFstTrace : std::false_type {};
template <typename M>
struct HasFstTrace<M, std::void_t<decltype(std::declval<M&>().trace(std::declval<VerilatedFstC*>(), 0))>>
    : std::true_type {};

// Verilator's edge detectors (its memory of each clock at the last
// evaluation), where this Verilator names them as 5.006 does.
template <typename M, typename = void>
struct HasClockMemory : std::false_type {};
template <typename M>
struct HasClockMemory<M, std::void_t<decltype(std::declval<M&>().rootp->__Vtrigrprev__TOP__clk_i),
                                     decltype(std::declval<M&>().rootp->__Vtrigrprev__TOP__dda_clk_i),
                                     decltype(std::declval<M&>().rootp->__VactTriggered)>>
    // Exactly those two clocks trigger anything: another would need its memory reset too.
    : std::bool_constant<std::is_same_v<std::decay_t<decltype(std::declval<M&>().rootp->__VactTriggered)>,
                                        VlTriggerVec<2>>> {};

template <typename Model>
class BackendRtlCore final : public BackendRtl {
 public:
  BackendRtlCore(const Params& p, uint32_t x_seed)
      : params_(p), layout_(rtl_layout(p)), fifo_levels_(p.base_tick_ns * 1e-9) {
    if (x_seed != 0) {
      ctx_.randReset(2);
      ctx_.randSeed(static_cast<int>(x_seed));
    }
    if constexpr (HasFstTrace<Model>::value) ctx_.traceEverOn(true);
    top_ = std::make_unique<Model>(&ctx_, "TOP");
    require_rtl_build(p);  // values fixed when the RTL was verilated
    Model& t = *top_;
    // Run-time inputs; params.cpp holds each to its port's width.
    set_port(t.dda_period_ticks_i, p.ticks(p.dda_clock_ns), kRtlDdaPeriodBits);
    set_port(t.had_access_ticks_i, p.ticks(p.had_access_ns), kRtlTimeBits);
    set_port(t.had_blend_ticks_i, p.ticks(p.had_blend_extra_ns), kRtlTimeBits);
    set_port(t.vram_cycle_ticks_i, p.ticks(p.vram_cycle_ns), kRtlTimeBits);
    set_port(t.clear_ticks_i, int64_t(frame_clear_ticks(p)), kRtlLongTimeBits);
    set_port(t.vram_steal_period_ticks_i, p.ticks(p.vram_steal_every_ns), kRtlLongTimeBits);
    period_ = static_cast<uint64_t>(p.ticks(p.dda_clock_ns));
    steal_period_ = static_cast<uint64_t>(p.ticks(p.vram_steal_every_ns));
    // Params holds 1 <= depth <= max_depth; code that sets the depth itself must too.
    if (p.fifo_dda_had_depth < 1 || p.fifo_dda_had_depth > p.fifo_max_depth)
      throw std::logic_error("FIFO limit " + std::to_string(p.fifo_dda_had_depth) + " outside 1..fifo.max_depth");
    set_port(t.fifo_limit_i, p.fifo_dda_had_depth, layout_.fifo_count_bits);
    t.write_behind_i = p.had_write_behind;
    t.prefetch_i = p.had_prefetch;
    t.dirty_bits_i = p.had_dirty_bits;
    t.one_minus_exact_i = p.one_minus_nf == OneMinusNf::kExact;
    t.walk_fix_i = p.walk_fix;
    t.pipelined_compare_i = p.xy_compare_pipelined;
    t.in_valid_i = 0;
    t.clear_i = t.flush_i = t.swap_i = 0;
    t.rst_ni = 0;
    t.dda_clk_i = 0;
    t.ticks_i = 1;
    for (int i = 0; i < 4; ++i) tick(kOneTick);
    t.rst_ni = 1;
    inputs_written();
    ticks_ = 0;
    state_clocks_.fill(0);
  }
  ~BackendRtlCore() override { top_->final(); }

  void begin_frame(const FrameSettings& s) override {
    Model& t = *top_;
    const Rgb bg = s.background;
    drain();
    const int c = params_.ep_color.out_bits;
    set_port(t.background_i, (int64_t(bg.r) << (2 * c)) | (int64_t(bg.g) << c) | bg.b, 3 * c);
    t.clear_i = 1;
    inputs_written();
    tick(kOneTick);
    t.clear_i = 0;
    inputs_written();
    drain();
    if (maps_) maps_->begin_frame();
  }

  void draw(const DdaParams& d) override {
    Model& t = *top_;
    ++triangles_;
    source_lines_.push_back(d.source_line);
    load_dda_ports(t, d, params_);
    t.in_valid_i = 1;
    inputs_written();
    for (uint64_t guard = 0;; ++guard) {
      clock_low();
      const bool taken = t.in_ready_o;  // ready only on a DDA clock: the load happens at this edge
      if (taken && maps_) maps_->loaded(t.dda_clocks_o, dda_pixels_in_flight());
      // The RTL's quiet_o cannot see the offer: an enabled tick is never warped over here.
      tick(ticks_ % period_ == 0 ? kOneTick : UINT64_MAX, kLowSettled);
      if (taken) break;
      if (guard > (uint64_t{1} << 28)) throw std::logic_error("RTL DDA did not take a parameter set within 2^28 ticks");
    }
    t.in_valid_i = 0;
    inputs_written();
  }

  void end_frame() override {
    Model& t = *top_;
    drain();
    t.flush_i = 1;
    inputs_written();
    tick(kOneTick);
    t.flush_i = 0;
    inputs_written();
    tick(kOneTick);
    drain();
    t.swap_i = 1;
    inputs_written();
    tick(kOneTick);
    t.swap_i = 0;
    inputs_written();
  }

  void drain() override {
    clock_until([](const Model& t) { return bool(t.idle_o); }, "the RTL back end did not go idle");
    if (maps_) maps_->idle(top_->dda_clocks_o);
  }

  // Clocks until the DDA could take a parameter set on this tick.
  uint64_t ready_tick() override {
    top_->in_valid_i = 0;
    inputs_written();
    clock_until([](const Model& t) { return bool(t.in_ready_o); }, "the RTL DDA did not become ready");
    return ticks_;
  }

  // Clocks with no input up to `target`. A back end that is idle (DDA,
  // FIFO, HAD and VRAM) on a DDA clock stays so, and nothing in it counts:
  // whole DDA periods are skipped without clocking (the clock-enable phase
  // is unchanged by a multiple of its period). Not with stolen VRAM cycles
  // (a free-running counter) or a tick hook (waveforms) attached.
  void idle_until(uint64_t target) override {
    Model& t = *top_;
    t.in_valid_i = 0;
    inputs_written();
    const bool may_skip = !on_tick_ && steal_period_ == 0;
    while (ticks_ < target) {
      if (may_skip && target - ticks_ >= period_) {
        clock_low();
        if (t.idle_o) {
          ticks_ += (target - ticks_) / period_ * period_;
          continue;
        }
        tick(target - ticks_, kLowSettled);
        continue;
      }
      tick(target - ticks_);
    }
  }

  uint64_t now_tick() const override { return ticks_; }

  // The RTL's own counters (ports), and the DDA clocks per state seen on them.
  BackendCounters counters() const override {
    const Model& t = *top_;
    return {t.dda_clocks_o, t.dda_wait_ticks_o, t.had_busy_ticks_o};
  }
  std::optional<ScreenMaps> screen_maps() const override {
    if (!maps_) return std::nullopt;
    return maps_->maps();
  }
  std::optional<FifoSeries> fifo_levels(uint64_t end) const override {
    if (!series_) return std::nullopt;
    return fifo_levels_.series(end);
  }
  BackendResult result() const override {
    const Model& t = *top_;
    BackendResult r;
    r.ticks = ticks_;
    r.triangles_drawn = triangles_;
    r.pixels_generated = t.pixels_generated_o;
    r.had = HadCounts{t.written_o, t.blended_o, t.z_rejected_o, t.dropped_o};
    r.dda.cycles = t.dda_clocks_o;
    r.dda.emitted = t.pixels_generated_o;
    r.dda.per_state = state_clocks_;
    r.dda.triangles = triangles_;
    r.dda.numerics = read_numerics(t, source_lines_);
    r.dda_wait_ticks = t.dda_wait_ticks_o;
    r.page_misses = t.page_misses_o;
    r.had_busy_ticks = t.had_busy_ticks_o;
    r.had_vram_wait_ticks = t.had_vram_wait_ticks_o;
    r.fifo_max = t.fifo_max_o;
    return r;
  }

  // The VRAM read through the backdoor, pixel by pixel (row-major), each at
  // its word address {page number, pixel in the page}.
  RgbImage shown() const override {
    const auto& mem = vram();
    const BitField shown = top_->front_o ? layout_.vram.rgb1 : layout_.vram.rgb0;
    const int c = params_.ep_color.out_bits;
    RgbImage img;
    img.width = params_.screen_width;
    img.height = params_.screen_height;
    std::vector<uint8_t>& out = img.rgb;
    out.resize(size_t(params_.screen_width) * size_t(params_.screen_height) * 3);
    size_t o = 0;
    for (int y = 0; y < params_.screen_height; ++y)
      for (int x = 0; x < params_.screen_width; ++x) {
        const uint64_t rgb = bits(mem[layout_.page.vram_address(x, y)], shown);
        for (int k = 2; k >= 0; --k) out[o++] = static_cast<uint8_t>(rgb >> (k * c));
      }
    return img;
  }

  std::vector<uint16_t> z_plane() const override {
    const auto& mem = vram();
    std::vector<uint16_t> out(size_t(params_.screen_width) * size_t(params_.screen_height));
    size_t o = 0;
    for (int y = 0; y < params_.screen_height; ++y)
      for (int x = 0; x < params_.screen_width; ++x)
        out[o++] = static_cast<uint16_t>(bits(mem[layout_.page.vram_address(x, y)], layout_.vram.z));
    return out;
  }

  void on_tick(std::function<void(const BackendRtl::TickProbe&)> hook) override { on_tick_ = std::move(hook); }
  void record_screen_maps() override { maps_.emplace(params_); }
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
      clock_low();
      if (done(t)) return;
      if (guard > (uint64_t{1} << 28)) throw std::logic_error(std::string(what) + " within 2^28 ticks (a deadlock)");
      tick(UINT64_MAX, kLowSettled);
    }
  }

  // One base tick, or up to `most` ticks at once where the RTL says nothing
  // but its timers and counters would run in them (its quiet_o: the tick
  // warp, hw/backend). Ticks that carry a control pulse, and every tick
  // while a hook watches (waveforms), are single.
  static constexpr uint64_t kOneTick = 1;
  static constexpr bool kLowSettled = true;  // the caller has just evaluated the clock low, inputs unchanged since
  // Both clocks low (the DDA's rises only with clk_i, on dda_step_o). Right
  // after this harness's own rising edge, with no input written since, the
  // outputs are already settled for the clock low: only the edge detectors
  // must see it low, which saves an evaluation per tick. Otherwise, and
  // with a tick hook (waveforms), an evaluation.
  void clock_low() {
    Model& t = *top_;
    t.clk_i = 0;
    t.dda_clk_i = 0;
    if constexpr (HasClockMemory<Model>::value) {
      if (after_own_edge_ && !on_tick_) {
        t.rootp->__Vtrigrprev__TOP__clk_i = 0;
        t.rootp->__Vtrigrprev__TOP__dda_clk_i = 0;
        after_own_edge_ = false;
        return;
      }
    }
    t.eval();
    after_own_edge_ = false;
  }
  void inputs_written() { after_own_edge_ = false; }
  void tick(uint64_t most = UINT64_MAX, bool low_settled = false) {
    Model& t = *top_;
    if (!low_settled) clock_low();
    if (t.dda_active_o && t.dda_state_o < state_clocks_.size()) ++state_clocks_[t.dda_state_o];
    BackendRtl::TickProbe probe{};
    if (on_tick_) {
      probe = {ticks_ + 1, false, bool(t.pixel_push_o), int(t.pixel_x_o), int(t.pixel_y_o)};
      on_tick_(probe);
    }
    if (maps_ && t.pixel_push_o) maps_->pushed(int(t.pixel_x_o), int(t.pixel_y_o));
    uint64_t span = on_tick_ ? 1 : std::max<uint64_t>(1, std::min<uint64_t>(t.quiet_o, most));
    if (span > period_) span -= span % period_;  // from an enabled tick, whole DDA periods (quiet_o's)
    t.ticks_i = static_cast<uint32_t>(span);
    t.clk_i = 1;
    t.dda_clk_i = t.dda_step_o;
    t.eval();
    after_own_edge_ = true;
    ticks_ += span;
    if (series_) fifo_levels_.level(ticks_, t.fifo_count_o);
    if (on_tick_) {
      probe.rising = true;
      on_tick_(probe);
    }
  }
  // Pixels in the DDA's output stages (through the backdoor, as vram()).
  uint64_t dda_pixels_in_flight() const {
    const auto& valid = top_->rootp->girtd_backend__DOT__u_dda__DOT__valid_q.m_storage;
    uint64_t n = 0;
    for (const auto v : valid) n += v;
    return n;
  }
  const auto& vram() const { return top_->rootp->girtd_backend__DOT__u_vram__DOT__mem; }
  static uint64_t bits(uint64_t word, const BitField& f) { return (word >> f.lsb) & uint64_t(max_of_bits(f.width)); }

  const Params& params_;
  const RtlLayout layout_;
  VerilatedContext ctx_;
  std::unique_ptr<Model> top_;
  uint64_t ticks_ = 0;
  uint64_t period_ = 1, steal_period_ = 0;  // DDA clock and VRAM steal period, in ticks
  std::array<uint64_t, static_cast<size_t>(DdaState::kCount)> state_clocks_{};
  uint64_t triangles_ = 0;
  std::vector<int> source_lines_;  // of each parameter set drawn (the first affected one's line)
  FifoLevels fifo_levels_;
  bool series_ = record_series();
  std::optional<RtlScreenMaps> maps_;  // report.html's heat maps, when asked for
  std::function<void(const BackendRtl::TickProbe&)> on_tick_;
  bool after_own_edge_ = false;  // the last evaluation was tick()'s rising edge, and no input was written since
};

}  // namespace girtd
