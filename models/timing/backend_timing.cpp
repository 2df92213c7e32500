#include "timing/backend_timing.hpp"

#include <algorithm>
#include <stdexcept>

namespace girtd {

BackendTimingModel::BackendTimingModel(const Params& p)
    : period_(p.ticks(p.dda_clock_ns)),
      access_(p.ticks(p.had_access_ns)),
      blend_(p.ticks(p.had_blend_extra_ns)),
      vram_(p.ticks(p.vram_cycle_ns)),
      limit_(p.fifo_dda_had_depth),
      clear_ticks_(frame_clear_ticks(p)),
      write_behind_(p.had_write_behind),
      dirty_bits_(p.had_dirty_bits),
      layout_(rtl_layout(p)),
      slot_page_(size_t(layout_.cache.pages), -1),
      slot_dirty_(size_t(layout_.cache.pages), false) {
  if (p.had_prefetch || p.vram_steal_every_ns > 0) stepped_ = std::make_unique<MemorySideTicks>(p);
}

void BackendTimingModel::on_fifo_stay(std::function<void(uint64_t push, uint64_t pop)> f) {
  if (stepped_) stepped_->on_pop(std::move(f));
}

void BackendTimingModel::on_page_miss(std::function<void(uint32_t page)> f) {
  if (stepped_) stepped_->on_page_miss(std::move(f));
  else on_miss_ = std::move(f);
}

uint64_t BackendTimingModel::next_en(uint64_t tick) const {
  return (tick + period_ - 1) / period_ * period_;
}

// Push and pop ticks both rise: each count picks up where the last one ended (TickWindow).
uint64_t BackendTimingModel::fifo_count_at(uint64_t tick) const {
  return pushes_.count_below(tick) - pops_.count_below(tick);
}

// The DDA holds a pixel while the FIFO is full at its tick `at`: it tries
// again every DDA clock. Jumps straight to the first clock after enough
// pops (no push happens meanwhile), counting the clocks lost.
uint64_t BackendTimingModel::wait_for_room(uint64_t at) {
  if (stepped_) {  // the pops before `at` are known once the memory side has run up to it
    for (stepped_->run_until(at); stepped_->fifo_count() >= uint64_t(limit_); stepped_->run_until(at)) {
      at += period_;
      ++t_.dda_wait_clocks;
    }
    return at;
  }
  for (uint64_t count = fifo_count_at(at); count >= uint64_t(limit_); count = fifo_count_at(at)) {
    const uint64_t frees_after = pops_[pops_.count_below(at) + (count - limit_)];  // that pop makes room
    const uint64_t clocks = (frees_after + 1 - at + period_ - 1) / period_;
    at += clocks * period_;
    t_.dda_wait_clocks += clocks;
  }
  return at;
}

// The HAD side of one pixel pushed at `tick` (hw/had: the pop tick is an
// access's first; a miss writes back and fetches, each one VRAM cycle, then
// accesses; a blend adds its own time).
void BackendTimingModel::push(const TimedPixel& p, uint64_t tick) {
  if (stepped_) {
    stepped_->push(layout_.page.number_of(p.x, p.y), p.outcome, tick);
    ++t_.pixels;
    return;
  }
  pushes_.push_back(tick);
  uint64_t pop = std::max(tick + 1, had_free_);
  const uint32_t page = layout_.page.number_of(p.x, p.y);
  const size_t slot = size_t(layout_.cache.slot_of(page));
  int64_t& in_slot = slot_page_[slot];
  uint64_t done;
  if (in_slot == int64_t(page)) {
    done = pop + std::max(access_, 2);
  } else {  // the slot's page (if any and, with dirty bits, if written) goes back, the new one comes in
    ++t_.page_misses;
    if (on_miss_) on_miss_(page);
    // A miss waits in IDLE for the write-behind write in flight.
    const uint64_t ready = std::max(pop, vram_free_);
    t_.had_vram_wait_ticks += ready - pop;
    pop = ready;
    const bool write_back = in_slot >= 0 && (slot_dirty_[slot] || !dirty_bits_);
    uint64_t loaded;
    if (write_back && write_behind_) {  // fetch first; the old page's write goes next, in the background
      loaded = pop + vram_;
      vram_free_ = loaded + 1 + vram_;
    } else {
      loaded = pop + (write_back ? 2 * vram_ : vram_);
    }
    t_.had_vram_wait_ticks += loaded - pop;
    done = loaded + 1 + std::max(access_, 1);
    in_slot = page;
    slot_dirty_[slot] = false;
  }
  pops_.push_back(pop);
  if (p.outcome == HadOutcome::kWritten || p.outcome == HadOutcome::kBlended) slot_dirty_[slot] = true;
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

// The load takes one enabled tick; clock c of the triangle comes P ticks
// later per clock; an emitted pixel is pushed on the clock it leaves the
// DDA (its `cycle`), and the DDA waits while the FIFO is full at that tick.
void BackendTimingModel::begin_triangle() {
  tri_clock0_ = next_en(dda_at_) + period_;  // clock 0 (CHECK)
  tri_wait_ticks_ = 0;
  tri_last_push_.reset();
}

void BackendTimingModel::pixel(const TimedPixel& p) {
  const uint64_t due = tri_clock0_ + p.cycle * uint64_t(period_) + tri_wait_ticks_;
  const uint64_t at = wait_for_room(due);
  tri_wait_ticks_ += at - due;
  push(p, at);
  if (!stepped_) {
    const uint64_t count_after = fifo_count_at(at + 1);
    t_.fifo_max = std::max<int>(t_.fifo_max, int(count_after));
    if (at >= watch_at_) [[unlikely]] {
      watch_at_ = watch_(pushes_.size() > 1 ? recent_push(1) : FifoPush{0, 0}, watch_peak_, {at, count_after});
      watch_peak_ = 0;
    }
    watch_peak_ = std::max(watch_peak_, count_after);
  }
  tri_last_push_ = at;
}

// The windows hold the pixels pushed since any pixel they dropped was popped
// (the FIFO holds fewer), so the count after an earlier push still held
// follows from them.
FifoPush BackendTimingModel::recent_push(size_t from_back) const {
  const uint64_t tick = pushes_[pushes_.size() - 1 - from_back];
  return {tick, fifo_count_at(tick + 1)};
}

BackendTimingModel::FifoWatchState BackendTimingModel::fifo_watch() const {
  if (pushes_.empty()) return {std::nullopt, watch_peak_};
  return {recent_push(0), watch_peak_};
}

void BackendTimingModel::end_triangle(uint64_t dda_cycles) {
  uint64_t at = tri_clock0_ + dda_cycles * uint64_t(period_) + tri_wait_ticks_;
  // A pixel leaving after the triangle's last clock (an output latency beyond it).
  if (tri_last_push_ && *tri_last_push_ >= at) at = *tri_last_push_ + period_;
  t_.dda_clocks += dda_cycles;
  dda_at_ = at;
  t_.ticks = std::max(t_.ticks, at);
  if (stepped_) take_stepped_counts();  // read between drains (report.html's timelines)
}

void BackendTimingModel::triangle(uint64_t dda_cycles, const std::vector<TimedPixel>& pixels) {
  begin_triangle();
  for (const TimedPixel& p : pixels) pixel(p);
  end_triangle(dda_cycles);
}

// The back end is idle only on a DDA clock: the DDA shows it is ready for a
// parameter set on an enabled tick (hw/dda in_ready_o), so an idle back end
// is seen at the first enabled tick once the DDA, the HAD and the VRAM (a
// write-behind write in flight) are done.
void BackendTimingModel::drain() {
  if (stepped_) return drain_stepped();
  t_.ticks = next_en(std::max({t_.ticks, dda_at_, had_free_, vram_free_}));
  dda_at_ = t_.ticks;
}

void BackendTimingModel::begin_frame() {
  drain();
  if (stepped_) {  // the clear is requested on this tick; the back end is then seen idle again
    stepped_->clear();
    t_.ticks += 1;
    drain_stepped();
  } else {
    t_.ticks = next_en(t_.ticks + clear_ticks_);  // seen idle again on a DDA clock
  }
  dda_at_ = t_.ticks;
  had_free_ = t_.ticks;
  std::fill(slot_page_.begin(), slot_page_.end(), -1);
  std::fill(slot_dirty_.begin(), slot_dirty_.end(), false);
}

void BackendTimingModel::end_frame() {
  if (stepped_) return end_frame_stepped();
  drain();
  // The flush request, then slot by slot: a tick to look at it and, for a
  // page, its write-back (the HAD's FLUSH state, counted busy as the RTL does).
  t_.ticks += 1;
  for (size_t slot = 0; slot < slot_page_.size(); ++slot) {
    int64_t& in_slot = slot_page_[slot];
    t_.ticks += 1;
    if (in_slot >= 0) {  // written back, or (clean, with dirty bits) only forgotten: one FLUSH tick
      const uint64_t flush = slot_dirty_[slot] || !dirty_bits_ ? vram_ : 1;
      t_.ticks += flush;
      t_.had_busy_ticks += flush;
    }
    in_slot = -1;
    slot_dirty_[slot] = false;
  }
  t_.ticks = next_en(t_.ticks) + 1;  // the swap, once the back end is seen idle (a DDA clock)
  dda_at_ = had_free_ = t_.ticks;
}

// The first DDA clock from the later of the DDA's end and the last tick
// seen on which the memory side is idle too.
void BackendTimingModel::drain_stepped() {
  uint64_t at = next_en(std::max({t_.ticks, dda_at_, stepped_->now()}));
  const uint64_t from = at;
  for (stepped_->run_until(at); !stepped_->idle(); stepped_->run_until(at)) {
    at += period_;
    if (at - from > (uint64_t{1} << 28)) throw std::logic_error("the stepped memory side did not go idle (a deadlock)");
  }
  t_.ticks = at;
  dda_at_ = at;
  take_stepped_counts();
}

// As the RTL driver does it: drain, the flush request for a tick and one
// more tick, drain (the HAD writes the cache back), the swap's tick.
void BackendTimingModel::end_frame_stepped() {
  drain_stepped();
  stepped_->flush();
  stepped_->run_until(t_.ticks + 2);
  t_.ticks += 2;
  drain_stepped();
  stepped_->run_until(t_.ticks + 1);
  t_.ticks += 1;
  dda_at_ = t_.ticks;
  take_stepped_counts();
}

void BackendTimingModel::take_stepped_counts() {
  t_.page_misses = stepped_->page_misses();
  t_.had_busy_ticks = stepped_->busy_ticks();
  t_.had_vram_wait_ticks = stepped_->vram_wait_ticks();
  t_.fifo_max = int(stepped_->fifo_max());
}

}  // namespace girtd
