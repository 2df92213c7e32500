// Cycle-approximate timing of GIRTD's back end (DDA -> FIFO -> HAD + cache
// -> VRAM), pixel by pixel instead of tick by tick: the event model the
// approx back end will use. It follows hw/backend's rules in base ticks: the
// DDA acts on every dda-period-th tick and waits while the FIFO is full; the
// HAD pops a pixel, spends an access (plus a blend) on a hit, and on a page
// miss writes the old page back and fetches the new one (two VRAM cycles).
// Models the design as written and two memory-side options: write-behind
// (a miss fetches first; the old page is written next, in the background,
// and the next miss waits for that write) and dirty bits (a page no pixel
// was written to is not written back, on a miss or at the frame's end).
// With prefetch or stolen VRAM cycles the memory side is stepped tick by
// tick instead (memory_side_ticks.*), the DDA side still by events. A cache
// hit takes at least two ticks, as in the RTL. Checked against the RTL's
// tick counts by testbench/unit/test_backend_timing.cpp.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "config/params.hpp"
#include "layout/rtl_layout.hpp"
#include "had/had.hpp"
#include "timing/memory_side_ticks.hpp"
#include "timing/tick_window.hpp"

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
  uint64_t pixels = 0;
  int fifo_max = 0;
};

// A pixel pushed into the DDA -> HAD FIFO on `tick`: the FIFO holds
// `count_after` pixels (it included) from tick + 1 on.
struct FifoPush {
  uint64_t tick, count_after;
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
  void pixel(const TimedPixel& p);
  void end_triangle(uint64_t dda_cycles);
  void end_frame();    // drain, write the cache page back, swap
  void drain();        // until the DDA and the HAD are idle

  const BackendTiming& timing() const { return t_; }
  // The FIFO's occupancy over time. Pixel by pixel, a pixel's pop is known
  // as it is pushed: recent_pops(), the pop ticks of the last
  // fifo.dda_had_depth + 2 pixels (more than the FIFO can hold) in push
  // order; with the stepped memory side only once it leaves: each pixel's
  // push and pop ticks told to on_fifo_stay's `f` then.
  bool stays_known_at_push() const { return !stepped_; }
  const TickWindow& recent_pops() const { return pops_; }
  void on_fifo_stay(std::function<void(uint64_t push, uint64_t pop)> f);
  // report.html's FIFO series without a call per pixel: the model keeps the
  // largest count after a push since it last called `f`, and calls it on
  // the first push on or after the tick `f` last returned (the last tick of
  // the watcher's bin), with the push before it and that largest count (this
  // push's not included). First call: on the first push. Not with the
  // stepped memory side. fifo_watch() is the same for the last push, for the end.
  using FifoWatch = std::function<uint64_t(FifoPush before, uint64_t peak, FifoPush now)>;
  void watch_fifo(FifoWatch f) {
    watch_ = std::move(f);
    watch_at_ = 0;
  }
  struct FifoWatchState {
    std::optional<FifoPush> last;
    uint64_t peak;
  };
  FifoWatchState fifo_watch() const;
  // Each page miss's page (report.html's heat map), as the HAD takes it.
  void on_page_miss(std::function<void(uint32_t page)> f);
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
  void push(const TimedPixel& p, uint64_t tick);
  uint64_t fifo_count_at(uint64_t tick) const;  // pushed before `tick` and not popped before it
  // 0: the last push, 1: the one before (exact for these two only: further
  // back, a pixel the windows dropped may not have been popped yet).
  FifoPush recent_push(size_t from_back) const;
  uint64_t wait_for_room(uint64_t at);            // the first DDA tick from `at` with room in the FIFO
  void drain_stepped();  // drain(), end_frame() and begin_frame() with the stepped memory side
  void end_frame_stepped();
  void take_stepped_counts();

  int period_, access_, blend_, vram_, limit_;
  uint64_t clear_ticks_;
  bool write_behind_, dirty_bits_;
  RtlLayout layout_;       // which pixels share a cache page, which slot a page takes
  uint64_t dda_at_ = 0;    // the DDA's next enabled tick
  uint64_t had_free_ = 0;  // the HAD's next IDLE tick
  std::vector<int64_t> slot_page_;  // the page in each cache slot, -1: none
  std::vector<bool> slot_dirty_;    // a pixel was written to it since it came in (had.dirty_bits)
  uint64_t vram_free_ = 0;          // the first tick the VRAM takes a request after a write-behind write
  TickWindow pops_;  // pop ticks of pixels possibly still in the FIFO
  TickWindow pushes_;
  FifoWatch watch_;
  // The next push tick watch_ hears of (none unwatched: no test per pixel), the peak until then.
  uint64_t watch_at_ = std::numeric_limits<uint64_t>::max(), watch_peak_ = 0;
  uint64_t tri_clock0_ = 0, tri_wait_ticks_ = 0;  // the triangle being streamed
  std::optional<uint64_t> tri_last_push_;
  BackendTiming t_;
  std::function<void(uint32_t)> on_miss_;
  std::unique_ptr<MemorySideTicks> stepped_;  // with prefetch or stolen cycles: the memory side, tick by tick
};

}  // namespace girtd
