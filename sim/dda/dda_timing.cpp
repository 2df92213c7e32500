#include "dda/dda_timing.hpp"

#include <algorithm>
#include <stdexcept>

namespace girtd {

BackendTimingModel::BackendTimingModel(const Params& p)
    : period_(uint64_t(p.ticks(p.dda_clock_ns))),
      limit_(uint64_t(p.fifo_dda_had_depth)),
      layout_(rtl_layout(p)),
      memory_(p) {}

uint64_t BackendTimingModel::next_en(uint64_t tick) const {
  return (tick + period_ - 1) / period_ * period_;
}

// The DDA holds a pixel while the FIFO is full at its tick `at`: it tries
// again every DDA clock, counting the clocks lost. The pops before `at` are
// known once the memory side has run up to it; pixel() calls this only when
// the pixels not yet popped could fill the FIFO (else the memory side runs
// later, many pixels at once).
uint64_t BackendTimingModel::wait_for_room(uint64_t at) {
  for (;;) {
    // While the HAD is busy with a pixel it pops none: every pixel pushed
    // (each before `at`) is still in on the ticks up to its IDLE tick, and
    // a pop on that tick makes room from the next one.
    const uint64_t held = memory_.held_until();
    if (at <= held) {
      const uint64_t clocks = (held - at) / period_ + 1;
      at += clocks * period_;
      t_.dda_wait_clocks += clocks;
    }
    memory_.run_until(at);
    if (memory_.fifo_count() < limit_) return at;
    at += period_;
    ++t_.dda_wait_clocks;
  }
}

// The load takes one enabled tick; clock c of the triangle comes P ticks
// later per clock; an emitted pixel is pushed on the clock it leaves the
// DDA (its `cycle`), and the DDA waits while the FIFO is full at that tick.
void BackendTimingModel::begin_triangle() {
  tri_clock0_ = next_en(dda_at_) + period_;  // clock 0 (CHECK)
  tri_wait_ticks_ = 0;
  tri_last_push_.reset();
}

void BackendTimingModel::end_triangle(uint64_t dda_cycles) {
  uint64_t at = tri_clock0_ + dda_cycles * period_ + tri_wait_ticks_;
  // A pixel leaving after the triangle's last clock (an output latency beyond it).
  if (tri_last_push_ && *tri_last_push_ >= at) at = *tri_last_push_ + period_;
  t_.dda_clocks += dda_cycles;
  dda_at_ = at;
  t_.ticks = std::max(t_.ticks, at);
  memory_.run_until(at);
  take_counts();  // read between drains (report.html's timelines)
}

void BackendTimingModel::triangle(uint64_t dda_cycles, const std::vector<TimedPixel>& pixels) {
  begin_triangle();
  for (const TimedPixel& p : pixels) pixel(p);
  end_triangle(dda_cycles);
}

// The back end is idle only on a DDA clock: the DDA shows it is ready for a
// parameter set on an enabled tick (hw/dda in_ready_o), so an idle back end
// is seen at the first DDA clock from the later of the DDA's end and the
// last tick seen on which the memory side is idle too.
void BackendTimingModel::drain() {
  uint64_t at = next_en(std::max({t_.ticks, dda_at_, memory_.now()}));
  const uint64_t from = at;
  for (memory_.run_until(at); !memory_.idle(); memory_.run_until(at)) {
    at += period_;
    if (at - from > (uint64_t{1} << 28)) throw std::logic_error("the memory side did not go idle (a deadlock)");
  }
  t_.ticks = at;
  dda_at_ = at;
  take_counts();
}

// The serial-port clear is requested on the tick the back end is seen idle;
// it is then seen idle again once the VRAM is done.
void BackendTimingModel::begin_frame() {
  drain();
  memory_.clear();
  t_.ticks += 1;
  drain();
}

// As the RTL driver does it: drain, the flush request for a tick and one
// more tick, drain (the HAD writes the cache back), the swap's tick.
void BackendTimingModel::end_frame() {
  drain();
  memory_.flush();
  memory_.run_until(t_.ticks + 2);
  t_.ticks += 2;
  drain();
  memory_.run_until(t_.ticks + 1);
  t_.ticks += 1;
  dda_at_ = t_.ticks;
  take_counts();
}

void BackendTimingModel::take_counts() {
  memory_.tell_fifo_stays();
  t_.page_misses = memory_.page_misses();
  t_.had_busy_ticks = memory_.busy_ticks();
  t_.had_vram_wait_ticks = memory_.vram_wait_ticks();
  t_.fifo_max = int(memory_.fifo_max());
}

}  // namespace girtd
