// Cycle-approximate timing of GIRTD's back end (DDA -> FIFO -> HAD + cache
// -> VRAM), as the approx back end runs it: the DDA side by events (it acts
// on every dda-period-th tick, pushes each pixel on the clock it leaves the
// DDA and waits while the FIFO is full), the memory side (FIFO, HAD, cache,
// VRAM with every option hw/ has) by memory_side_ticks.*, run up to each
// tick the DDA acts on. Checked against the RTL's tick counts by
// testbench/unit/test_backend_timing.cpp.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "config/params.hpp"
#include "layout/rtl_layout.hpp"
#include "had/memory_side_ticks.hpp"

namespace girtd {

struct TimedPixel {
  uint64_t cycle;      // DDA clock the pixel leaves, within its triangle (golden DdaEmit::cycle)
  int x, y;
  HadOutcome outcome;  // what the HAD does with it (from the golden HAD)
};

struct BackendTiming {
  uint64_t ticks = 0;            // base ticks since the model started
  uint64_t dda_clocks = 0;       // DDA clocks on triangles (loads excluded)
  uint64_t dda_wait_clocks = 0;  // DDA clocks lost on a full FIFO
  uint64_t page_misses = 0;
  uint64_t had_busy_ticks = 0;       // a pixel in hand (pop to done)
  uint64_t had_vram_wait_ticks = 0;  // of those, waiting for a page (write-back and fetch)
  int fifo_max = 0;
};

class BackendTimingModel {
 public:
  explicit BackendTimingModel(const Params& p);

  void begin_frame();  // the serial-port clear; the cache starts empty
  // One triangle: its DDA clock count and its pixels in emission order;
  // or the same as a stream (begin, each pixel as the DDA emits it, end).
  // A pixel is pushed on the clock it leaves the DDA (its `cycle`); one
  // leaving after the triangle's last clock (an output latency of 3 or more)
  // holds the DDA until it is pushed.
  void triangle(uint64_t dda_cycles, const std::vector<TimedPixel>& pixels);
  void begin_triangle();
  // Inline: called for every pixel the DDA emits.
  void pixel(const TimedPixel& p) {
    const uint64_t due = tri_clock0_ + p.cycle * period_ + tri_wait_ticks_;
    const uint64_t at = memory_.pending() < limit_ ? due : wait_for_room(due);
    tri_wait_ticks_ += at - due;
    memory_.push(layout_.page.number_of(p.x, p.y), p.outcome, at);
    tri_last_push_ = at;
  }
  void end_triangle(uint64_t dda_cycles);
  void end_frame();    // drain, write the cache page back, swap
  void drain();        // until the DDA and the HAD are idle

  const BackendTiming& timing() const { return t_; }
  // Each pixel's FIFO stay, in push order, told in batches as pixels leave
  // (and at each triangle's end): report.html's FIFO series.
  void on_fifo_stays(PixelFifoTicks::StaysListener f) { memory_.on_fifo_stays(std::move(f)); }
  // Each page miss's page (report.html's heat map), as the HAD takes it.
  void on_page_miss(std::function<void(uint32_t page)> f) { memory_.on_page_miss(std::move(f)); }
  // The tick the DDA can take its next parameter set (its first enabled
  // tick once the previous triangle is done), and a parameter set that
  // arrives later than that: the DDA idles until `tick`.
  uint64_t dda_ready_tick() const { return next_en(dda_at_); }
  void idle_until(uint64_t tick) { dda_at_ = std::max(dda_at_, tick); }
  // A triangle not simulated (sampled timing): the DDA is taken for `ticks`
  // from its ready tick, the HAD and FIFO go on with what they hold.
  void skip_triangle(uint64_t ticks) {
    dda_at_ = next_en(dda_at_) + ticks;
    t_.ticks = std::max(t_.ticks, dda_at_);
  }

 private:
  uint64_t next_en(uint64_t tick) const;  // first DDA-enabled tick at or after `tick`
  uint64_t wait_for_room(uint64_t at);    // the first DDA tick from `at` with room in the FIFO (called when the pixels not yet popped could fill it)
  void take_counts();

  uint64_t period_, limit_;
  RtlLayout layout_;     // which cache page a pixel is in
  uint64_t dda_at_ = 0;  // the DDA's next enabled tick
  uint64_t tri_clock0_ = 0, tri_wait_ticks_ = 0;  // the triangle being streamed
  std::optional<uint64_t> tri_last_push_;
  BackendTiming t_;
  MemorySideTicks memory_;
};

}  // namespace girtd
