// hw/fifo between the DDA and the HAD, over ticks, without its data: each
// pixel's push tick, page and what the HAD will do with it (the golden
// HAD's outcome). A pixel pushed on tick t is in the FIFO's count from
// t + 1; pixels may be pushed ahead of the tick the memory side has
// reached (sim/had/memory_side_ticks.hpp), so the count is asked for a
// tick. Each pixel's stay (push and pop tick) is told to a listener in
// batches: a call per pixel cost more than the series it feeds
// (fifo_levels.hpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

#include "common/block_queue.hpp"
#include "had/had.hpp"

namespace girtd {

struct FifoPixel {
  uint64_t tick;  // pushed on
  uint32_t page;
  HadOutcome outcome;
};

class PixelFifoTicks {
 public:
  struct Stay {
    uint64_t push, pop;
  };
  using StaysListener = std::function<void(const std::vector<Stay>&)>;

  // In push order, none before `now` (the tick the memory side has reached).
  void push(uint64_t tick, uint32_t page, HadOutcome outcome, uint64_t now) {
    if (tick < now || (!q_.empty() && tick <= q_.back().tick))
      throw std::logic_error("PixelFifoTicks: a pixel pushed before now or before the last one");
    FifoPixel& p = q_.push_back_slot();  // field by field: see push_back_slot
    p.tick = tick;
    p.page = page;
    p.outcome = outcome;
  }
  // The count on tick `now`: pixels pushed before it and not popped. Asked
  // for ticks that do not go back (a pop aside).
  uint64_t count(uint64_t now) const {
    while (seen_ < q_.size() && q_[seen_].tick < now) ++seen_;
    return seen_;
  }
  // The count on a later tick, no pop between. Scans from the count last asked for, which is at most the count at `tick`.
  uint64_t count_on(uint64_t tick) const {
    size_t n = seen_;
    while (n < q_.size() && q_[n].tick < tick) ++n;
    return n;
  }
  // The first tick the count grows on (after count(now)); the largest tick when nothing more is pending.
  uint64_t next_arrival() const {
    return seen_ < q_.size() ? q_[seen_].tick + 1 : std::numeric_limits<uint64_t>::max();
  }
  uint64_t pending() const { return q_.size(); }  // pushed and not popped, counted or not
  bool empty() const { return q_.empty(); }
  const FifoPixel& head() const { return q_.front(); }  // counted (count(now) != 0)
  void pop(uint64_t now) {  // the head leaves on tick `now`
    if (on_stays_) {
      stays_.push_back({q_.front().tick, now});
      if (stays_.size() == kStaysBatch) tell_stays();
    }
    q_.pop_front();
    --seen_;
  }

  void note_count(uint64_t n) { max_ = std::max(max_, n); }  // a count the HAD saw
  uint64_t max() const { return max_; }

  void on_stays(StaysListener f) { on_stays_ = std::move(f); }
  void tell_stays() {  // the stays not yet told
    if (stays_.empty()) return;
    on_stays_(stays_);
    stays_.clear();
  }

 private:
  static constexpr size_t kStaysBatch = 4096;
  BlockQueue<FifoPixel> q_;
  mutable size_t seen_ = 0;  // q_'s first entries, pushed before the last tick asked: the count
  uint64_t max_ = 0;
  StaysListener on_stays_;
  std::vector<Stay> stays_;  // popped, not yet told
};

}  // namespace girtd
