// The DDA -> HAD FIFO's occupancy over modeled time, for report.html, from
// what each back end knows of it:
// - rtl reads the FIFO's count after every edge it clocks (level());
// - approx knows each pixel's push and pop ticks (interval()), in FIFO
//   order, the pop possibly long before or after the next push is known;
//   its event model also knows the count just after each push, and keeps
//   the pops of the pixels that may still be in the FIFO, and tells the
//   pushes that leave a bin (follow(), push_leaving_bin()).
// A pixel pushed at tick p and popped at tick q is in the FIFO on ticks
// p+1 .. q (the count is a register, as hw/fifo's). The series holds the
// largest count in each bin, as the other FIFOs' series do.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "timeline/time_series.hpp"
#include "timing/backend_timing.hpp"
#include "timing/tick_window.hpp"

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
    last_push_ = push;
  }
  // The same from a model that keeps, in push order, the pops of at least
  // every pixel that may still be in the FIFO: `recent_pops` (it must
  // outlive this), and tells only some pushes (BackendTimingModel::
  // watch_fifo): inside the bin the open span started in, pushes only raise
  // its peak and pops only lower the count, so the model keeps that peak
  // and calls at the first push that leaves the bin (returned here): with
  // the push before it, the pops since that one are replayed from the model's.
  void follow(const TickWindow& recent_pops) { recent_ = &recent_pops; }
  uint64_t push_leaving_bin(FifoPush before, uint64_t peak, FifoPush now) {
    catch_up(before, peak);
    take_pending(false);  // the last pop held is this pixel's
    interval(now.tick, recent_->back());
    return span_bin_end_ > 0 ? span_bin_end_ - 1 : 0;
  }
  // The series up to tick `end` (the level then held carried to it).
  // Following a model: `last`, its last push, and the peak since it last called.
  FifoSeries series(uint64_t end, std::optional<FifoPush> last = std::nullopt, uint64_t peak = 0) const {
    FifoLevels done = *this;
    if (last) done.catch_up(*last, peak);
    if (recent_) done.take_pending(true);
    done.retire_pops_up_to(end);
    done.close_span(end);
    return done.series_;
  }

 private:
  // The pushes the model did not tell: the last one and their peak.
  void catch_up(FifoPush last, uint64_t peak) {
    count_ = last.count_after;
    last_push_ = last.tick;
    span_peak_ = std::max(span_peak_, peak);
  }
  // The open span, ticks span_from_ .. tick - 1: its peak in the bin it
  // started in (where all its changes were), its last count on every bin up
  // to half a tick before `tick` (a bin that starts at `tick` does not get it).
  void close_span(uint64_t tick) {
    if (tick <= span_from_) return;
    const double from = double(span_from_) * tick_s_;
    series_.note_max(0, from, from, double(span_peak_));
    series_.note_max(0, from, (double(tick) - 0.5) * tick_s_, double(count_));
  }
  // The pops after the last push, from the model's (those up to it are in
  // count_ already), but for the pixel being pushed unless `with_last`.
  void take_pending(bool with_last) {
    pops_.clear();
    const size_t n = recent_->size() - (with_last ? 0 : 1);
    for (size_t i = 0; i < n; ++i)
      if ((*recent_)[i] > last_push_) pops_.push_back((*recent_)[i]);
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
  TickWindow pops_;  // of pixels pushed, not yet retired
  const TickWindow* recent_ = nullptr;  // the model's, when following one
  uint64_t last_push_ = 0;
  FifoSeries series_{true};
};

}  // namespace girtd
