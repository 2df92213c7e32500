#include "timing/backend_timing.hpp"

#include <algorithm>

#include "common/input_error.hpp"

namespace girtd {

BackendTimingModel::BackendTimingModel(const Params& p)
    : period_(p.ticks(p.dda_clock_ns)),
      access_(p.ticks(p.had_access_ns)),
      blend_(p.ticks(p.had_blend_extra_ns)),
      vram_(p.ticks(p.vram_cycle_ns)),
      limit_(p.fifo_dda_had_depth),
      clear_ticks_(uint64_t(p.vram_serial_transfers) * (p.ticks(p.vram_serial_ns) + p.ticks(p.vram_cycle_ns))) {
  if (p.had_write_behind || p.had_prefetch || p.had_dirty_bits || p.vram_steal_every_ns > 0)
    throw InputError("--config", 0,
                     "the back-end timing model covers the design as written: turn off had.write_behind, "
                     "had.prefetch, had.dirty_bits and vram.steal_every_ns");
}

uint64_t BackendTimingModel::next_en(uint64_t tick) const {
  return (tick + period_ - 1) / period_ * period_;
}

uint64_t BackendTimingModel::fifo_count_at(uint64_t tick) const {
  uint64_t pushed = 0, popped = 0;
  for (uint64_t u : pushes_) pushed += u < tick;
  for (uint64_t s : pops_) popped += s < tick;
  return pushed - popped;
}

// The HAD side of one pixel pushed at `tick` (hw/had: the pop tick is an
// access's first; a miss writes back and fetches, each one VRAM cycle, then
// accesses; a blend adds its own time).
void BackendTimingModel::push(const TimedPixel& p, uint64_t tick) {
  pushes_.push_back(tick);
  const uint64_t pop = std::max(tick + 1, had_free_);
  pops_.push_back(pop);
  const int page = (p.y << 6) | (p.x >> 4);
  uint64_t done;
  if (cache_valid_ && page == cache_page_) {
    done = pop + std::max(access_, 2);
  } else {
    ++t_.page_misses;
    const uint64_t loaded = pop + (cache_valid_ ? 2 * vram_ : vram_);
    t_.had_vram_wait_ticks += loaded - pop;
    done = loaded + 1 + std::max(access_, 1);
    cache_valid_ = true;
    cache_page_ = page;
  }
  if (p.outcome == HadOutcome::kBlended) done += blend_;
  t_.had_busy_ticks += done - pop;
  had_free_ = done;
  ++t_.pixels;
  // Keep only what can still be in the FIFO.
  while (pops_.size() > size_t(limit_) + 2) {
    pops_.pop_front();
    pushes_.pop_front();
  }
}

void BackendTimingModel::triangle(uint64_t dda_cycles, const std::vector<TimedPixel>& pixels) {
  // The load takes one enabled tick; clock c of the triangle comes P ticks
  // later per clock; an emitted pixel is pushed one DDA clock after it is
  // emitted, and the DDA waits while the FIFO is full at that tick.
  uint64_t at = next_en(dda_at_) + period_;  // clock 0 (CHECK)
  size_t next = 0;
  for (uint64_t c = 0; c <= dda_cycles; ++c) {
    while (next < pixels.size() && pixels[next].cycle == c) {
      // Emitted on clock c - latency: pushed on this clock's tick if there is room.
      while (fifo_count_at(at) >= uint64_t(limit_)) {
        at += period_;
        ++t_.dda_wait_clocks;
      }
      push(pixels[next], at);
      t_.fifo_max = std::max<int>(t_.fifo_max, int(fifo_count_at(at + 1)));
      ++next;
    }
    if (c < dda_cycles) at += period_;
  }
  // Pixels leaving after the triangle's last clock (an output latency beyond it).
  for (; next < pixels.size(); ++next) {
    while (fifo_count_at(at) >= uint64_t(limit_)) {
      at += period_;
      ++t_.dda_wait_clocks;
    }
    push(pixels[next], at);
    at += period_;
  }
  t_.dda_clocks += dda_cycles;
  dda_at_ = at;
  t_.ticks = std::max(t_.ticks, at);
}

void BackendTimingModel::drain() {
  t_.ticks = std::max({t_.ticks, dda_at_, had_free_});
  dda_at_ = t_.ticks;
}

void BackendTimingModel::begin_frame() {
  drain();
  t_.ticks += clear_ticks_;
  dda_at_ = t_.ticks;
  had_free_ = t_.ticks;
  cache_valid_ = false;
}

void BackendTimingModel::end_frame() {
  drain();
  if (cache_valid_) t_.ticks += 2 + vram_;  // flush request and write-back
  cache_valid_ = false;
  t_.ticks += 1;  // swap
  dda_at_ = had_free_ = t_.ticks;
}

}  // namespace girtd
