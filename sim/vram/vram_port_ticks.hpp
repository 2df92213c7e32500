// hw/vram's port, tick by tick, without its data: one operation at a time
// (a page's read or write of one VRAM cycle, the frame clear, a stolen
// cycle); a stolen cycle comes due every vram.steal_every_ns (none when 0)
// and goes before anything else, a requested clear before the HAD's
// requests. State n is the registers after n ticks; the accessors are tick
// n's signals and edge() takes the clock edge, as the RTL does
// (sim/had/memory_side_ticks.hpp drives it).
#pragma once

#include <algorithm>
#include <cstdint>

#include "config/params.hpp"

namespace girtd {

class VramPortTicks {
 public:
  explicit VramPortTicks(const Params& p);

  uint64_t cycle() const { return cycle_; }  // a page's read or write, in ticks

  // ---- this tick's signals ----
  bool finishing() const { return vbusy_ && left_ == 1; }  // an operation's last tick
  bool port_busy() const { return vbusy_ && left_ != 1; }
  bool steal_due() const { return steals_owed_ != 0; }
  // A steal owed or a clear requested: the port is taken before any request.
  bool claimed() const { return steals_owed_ != 0 || clear_pending_; }
  // hw/vram's busy output: the HAD may not request (not on the clear request's own tick).
  bool busy() const { return port_busy() || claimed(); }
  // A request's own operation ends on this tick (a clear's or a steal's does not count).
  bool done() const { return finishing() && !clearing_ && !stealing_; }
  // Nothing on the port, due or waiting: only the steal counter counts.
  bool quiet() const { return !vbusy_ && !claimed(); }

  // Whether a steal comes due on the edges of the next `ticks` ticks.
  bool steal_within(uint64_t ticks) const { return steal_period_ != 0 && steal_count_ + ticks >= steal_period_; }
  // Up to `k`: the ticks from now on which the port only counts (no
  // operation ends, no steal comes due).
  uint64_t counting_ticks(uint64_t k) const {
    if (vbusy_) k = std::min(k, left_ - 1);
    if (steal_period_) k = std::min(k, steal_period_ - 1 - steal_count_);
    return k;
  }
  void count(uint64_t k) {  // `k` such ticks pass
    if (steal_period_) steal_count_ += k;
    if (vbusy_) left_ -= k;
  }

  // The clock edge: `req` the HAD's request for a page cycle, `clear_in`
  // the frame clear requested on this tick.
  void edge(bool req, bool clear_in);

 private:
  const uint64_t cycle_, clear_ticks_, steal_period_;
  bool vbusy_ = false, clearing_ = false, stealing_ = false, clear_pending_ = false;
  uint64_t left_ = 0, steal_count_ = 0;
  unsigned steals_owed_ = 0;  // 8 bits in hw/vram: saturates at 255
};

}  // namespace girtd
