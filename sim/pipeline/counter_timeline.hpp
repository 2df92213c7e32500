// The DDA's and the HAD's timelines for report.html, from the back end's own
// counters (BackendCounters) read whenever the DDA takes a parameter set and
// at every frame's clear and end: the busy and blocked time each gained since
// the last reading is spread evenly over the ticks between the two readings,
// and the rest counts as starved. A counter may run ahead of the reading's
// tick (approx counts a pixel's HAD time when it is pushed): what does not
// fit in the interval is carried to the next. Triangle resolution, for
// approx and rtl alike, at no per-tick cost; the totals are the counters'.
#pragma once

#include <algorithm>
#include <cstdint>

#include "backends/modeled_time.hpp"
#include "timeline/stage_activity.hpp"
#include "timeline/time_series.hpp"

namespace girtd {

class CounterTimeline {
 public:
  CounterTimeline(double tick_s, double dda_clock_s) : tick_s_(tick_s), clock_s_(dda_clock_s) {}

  void read(uint64_t now_tick, const BackendCounters& c) {
    if (now_tick <= tick_) return;
    const double t0 = double(tick_) * tick_s_, t1 = double(now_tick) * tick_s_, span = t1 - t0;
    owed_busy_ += double(c.dda_clocks - last_.dda_clocks) * clock_s_;
    owed_blocked_ += double(c.dda_wait_ticks - last_.dda_wait_ticks) * tick_s_;
    owed_had_ += double(c.had_busy_ticks - last_.had_busy_ticks) * tick_s_;
    const double busy = std::min(owed_busy_, span), blocked = std::min(owed_blocked_, span - busy);
    const double had_busy = std::min(owed_had_, span);
    owed_busy_ -= busy;
    owed_blocked_ -= blocked;
    owed_had_ -= had_busy;
    dda_.add_span(size_t(StageState::kBusy), t0, t1, busy / span);
    dda_.add_span(size_t(StageState::kBlocked), t0, t1, blocked / span);
    dda_.add_span(size_t(StageState::kStarved), t0, t1, std::max(0.0, span - busy - blocked) / span);
    had_.add_span(size_t(StageState::kBusy), t0, t1, had_busy / span);
    had_.add_span(size_t(StageState::kStarved), t0, t1, std::max(0.0, span - had_busy) / span);
    tick_ = now_tick;
    last_ = c;
  }
  const StageSeries& dda() const { return dda_; }
  const StageSeries& had() const { return had_; }

 private:
  double tick_s_, clock_s_;
  uint64_t tick_ = 0;
  BackendCounters last_;
  double owed_busy_ = 0, owed_blocked_ = 0, owed_had_ = 0;  // counted, not yet placed
  StageSeries dda_, had_;
};

}  // namespace girtd
