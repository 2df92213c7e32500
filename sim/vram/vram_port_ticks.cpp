#include "vram/vram_port_ticks.hpp"

#include <stdexcept>

#include "vram/vram_word.hpp"

namespace girtd {

VramPortTicks::VramPortTicks(const Params& p)
    : cycle_(std::max<uint64_t>(1, uint64_t(p.ticks(p.vram_cycle_ns)))),  // hw/vram: 0 ticks is 1
      clear_ticks_(frame_clear_ticks(p)),
      steal_period_(uint64_t(p.ticks(p.vram_steal_every_ns))) {}

void VramPortTicks::edge(bool req, bool clear_in) {
  const bool port_was_busy = port_busy(), steal_was_due = steal_due(), was_finishing = finishing();
  const bool steal_comes_due = steal_within(1);
  if (steal_period_) steal_count_ = steal_comes_due ? 0 : steal_count_ + 1;
  steals_owed_ = steals_owed_ + unsigned(steal_comes_due && steals_owed_ != 0xFF) -
                 unsigned(!port_was_busy && steal_was_due);
  if (vbusy_) --left_;
  if (was_finishing) vbusy_ = clearing_ = stealing_ = false;
  const bool clear_was_pending = clear_pending_ || clear_in;
  if (clear_in) clear_pending_ = true;
  if (!port_was_busy && steal_was_due) {  // a stolen cycle goes first
    vbusy_ = stealing_ = true;
    left_ = cycle_;
  } else if (!port_was_busy && clear_was_pending) {
    clear_pending_ = false;
    vbusy_ = clearing_ = true;
    left_ = clear_ticks_;
  } else if (!port_was_busy && req) {
    vbusy_ = true;
    left_ = cycle_;
  } else if (req) {
    throw std::logic_error("VramPortTicks: a VRAM request while the port is busy");
  }
}

}  // namespace girtd
