// The DDA -> HAD FIFO's occupancy over modeled time, for report.html, from
// what each back end knows of it:
// - rtl reads the FIFO's count after every edge it clocks (level());
// - approx knows each pixel's push and pop ticks (interval()), in FIFO
//   order, told once the pixel has left.
// A pixel pushed at tick p and popped at tick q is in the FIFO on ticks
// p+1 .. q (the count is a register, as hw/fifo's). The series holds the
// largest count in each bin, as the other FIFOs' series do.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "common/block_queue.hpp"
#include "timeline/time_series.hpp"

namespace girtd {

class FifoLevels {
 public:
  explicit FifoLevels(double tick_s) : tick_s_(tick_s) {}

  // The count from tick `tick` on is `count`.
  void level(uint64_t tick, uint64_t count) {
    if (count == count_) return;
    // Changes inside the bin the open span started in only raise its peak;
    // the span is noted once it leaves that bin (most changes cost a compare).
    if (tick >= span_bin_end_) {
      close_span(tick);
      span_from_ = tick;
      span_peak_ = 0;
      // The first tick of the next bin (bins only widen, when a span is noted).
      const double bin_ticks = series_.bin_s() / tick_s_;
      span_bin_end_ = uint64_t(std::ceil((std::floor(double(tick) / bin_ticks) + 1) * bin_ticks));
    }
    count_ = count;
    span_peak_ = std::max(span_peak_, count_);
  }
  // One pixel's stay; calls come in push order (so in pop order too).
  void interval(uint64_t push, uint64_t pop) {
    retire_pops_up_to(push);
    level(push + 1, count_ + 1);
    pops_.push_back(pop);
  }
  // The series up to tick `end` (the level then held carried to it).
  FifoSeries series(uint64_t end) const {
    FifoLevels done = *this;
    done.retire_pops_up_to(end);
    done.close_span(end);
    return done.series_;
  }

 private:
  // The open span, ticks span_from_ .. tick - 1: its peak in the bin it
  // started in (where all its changes were), its last count on every bin up
  // to half a tick before `tick` (a bin that starts at `tick` does not get it).
  void close_span(uint64_t tick) {
    if (tick <= span_from_) return;
    const double from = double(span_from_) * tick_s_;
    series_.note_max(0, from, from, double(span_peak_));
    series_.note_max(0, from, (double(tick) - 0.5) * tick_s_, double(count_));
  }
  void retire_pops_up_to(uint64_t tick) {
    while (!pops_.empty() && pops_.front() <= tick) {
      level(pops_.front() + 1, count_ - 1);
      pops_.pop_front();
    }
  }

  double tick_s_;
  uint64_t count_ = 0;
  uint64_t span_from_ = 0, span_peak_ = 0;  // the open span: its first tick, its largest count
  uint64_t span_bin_end_ = 0;               // and the first tick past the bin it started in
  BlockQueue<uint64_t> pops_;  // of pixels pushed, not yet retired
  FifoSeries series_{true};
};

}  // namespace girtd
