#include "had/memory_side_ticks.hpp"

#include <algorithm>
#include <stdexcept>

namespace girtd {

MemorySideTicks::MemorySideTicks(const Params& p)
    : layout_(rtl_layout(p)),
      access_(uint64_t(p.ticks(p.had_access_ns))),
      blend_(uint64_t(p.ticks(p.had_blend_extra_ns))),
      cycle_(std::max<uint64_t>(1, uint64_t(p.ticks(p.vram_cycle_ns)))),  // hw/vram: 0 ticks is 1
      clear_ticks_(frame_clear_ticks(p)),
      steal_period_(uint64_t(p.ticks(p.vram_steal_every_ns))),
      write_behind_(p.had_write_behind),
      prefetch_(p.had_prefetch),
      dirty_bits_(p.had_dirty_bits),
      valid_(size_t(layout_.cache.pages), 0),
      dirty_(size_t(layout_.cache.pages), 0),
      page_(size_t(layout_.cache.pages), 0) {}

void MemorySideTicks::push(uint32_t page, HadOutcome outcome, uint64_t tick) {
  // Pixels enter in the order the DDA pushes them, none before the tick the memory side has reached.
  if (tick < now_ || (!fifo_.empty() && tick <= fifo_.back().tick))
    throw std::logic_error("MemorySideTicks: a pixel pushed before now() or before the last one");
  fifo_.push_back({tick, page, outcome});
}

uint64_t MemorySideTicks::count_on(uint64_t tick) const {
  size_t n = fifo_count();  // tick >= now_
  while (n < fifo_.size() && fifo_[n].tick < tick) ++n;
  return n;
}

[[gnu::always_inline]] inline void MemorySideTicks::popped(const Entry& e) {
  if (on_stays_) {
    stays_.push_back({e.tick, now_});
    if (stays_.size() == kStaysBatch) tell_fifo_stays();
  }
  fifo_.pop_front();
  --seen_;
}

void MemorySideTicks::tell_fifo_stays() {
  if (stays_.empty()) return;
  on_stays_(stays_);
  stays_.clear();
}

bool MemorySideTicks::vram_busy() const {
  const bool port_busy = vbusy_ && left_ != 1;
  return port_busy || steals_owed_ != 0 || clear_pending_;  // as hw/vram: not the clear request's own tick
}

bool MemorySideTicks::idle() const {
  return now_ >= held_until_ && state_ == State::kIdle && !flush_pending_ && !wb_pending_ && !pf_loading_ &&
         fifo_.empty() && !vram_busy();
}

// Requested on now(): the driver asks once the back end is idle (a pixel
// still held would let the request take effect late).
void MemorySideTicks::clear() {
  if (!idle()) throw std::logic_error("MemorySideTicks: a frame clear requested while the back end is busy");
  clear_in_ = true;
}
void MemorySideTicks::flush() {
  if (!idle()) throw std::logic_error("MemorySideTicks: a flush requested while the back end is busy");
  flush_in_ = true;
}

MemorySideTicks::Signals MemorySideTicks::signals() const {
  // ---- this tick's signals, from the registers (hw/vram, hw/had) ----
  Signals g;
  g.in_fifo = fifo_count();
  const Entry* head = g.in_fifo ? &fifo_.front() : nullptr;
  g.head = head;

  g.finishing = vbusy_ && left_ == 1;
  g.port_busy = vbusy_ && !g.finishing;
  g.steal_due = steals_owed_ != 0;
  g.vbusy_o = vram_busy();
  g.done = g.finishing && !clearing_ && !stealing_;

  const size_t hslot = head ? slot_of(head->page) : 0;
  const bool victim_valid = head && valid_[hslot];
  g.head_hit = victim_valid && page_[hslot] == head->page;
  g.must_write_back = victim_valid && (dirty_[hslot] || !dirty_bits_);
  const bool head_in_pf = head && pf_page_ == head->page && (pf_valid_ || pf_loading_);
  g.fslot = flush_slot_;
  g.flush_valid = valid_[g.fslot];
  g.flush_write_back = g.flush_valid && (dirty_[g.fslot] || !dirty_bits_);
  g.idle = state_ == State::kIdle;
  g.background_ok = g.idle || state_ == State::kAccess || state_ == State::kBlend;
  g.miss_go = g.idle && head && !g.head_hit && !(head_in_pf && pf_loading_) && !g.vbusy_o && !wb_pending_ &&
              !pf_loading_;
  g.flush_step = g.idle && flush_pending_ && !head && !g.vbusy_o && !wb_pending_ && !pf_loading_;
  g.wb_issue = g.background_ok && wb_pending_ && !g.vbusy_o;
  g.pf_issue = prefetch_ && g.background_ok && !g.idle && !wb_pending_ && !g.vbusy_o && !pf_valid_ && !pf_loading_ &&
               head && victim_valid && !g.head_hit;
  g.pop = g.idle && head && (g.head_hit || g.miss_go);
  g.req = g.wb_issue || g.pf_issue;
  switch (state_) {
    case State::kIdle:
      if (head && g.head_hit) break;
      if (g.miss_go) g.req = g.req || (g.must_write_back && !write_behind_) || !(pf_valid_ && pf_page_ == head->page);
      else if (g.flush_step && g.flush_write_back) g.req = true;
      break;
    case State::kWriteBack:
    case State::kRefetch:
      if ((state_ == State::kRefetch || g.done) && !use_pf_ && !g.vbusy_o) g.req = true;
      break;
    default:
      break;
  }
  g.cache_load = state_ == State::kFetch && (use_pf_ || g.done);
  g.cache_write =
      (state_ == State::kAccess && count_ == 1 &&
       (pix_.outcome == HadOutcome::kWritten || (pix_.outcome == HadOutcome::kBlended && blend_ == 0))) ||
      (state_ == State::kBlend && count_ == 1);
  g.cache_invalidate = state_ == State::kFlush && (g.done || !g.flush_write_back);
  g.vram_wait = state_ == State::kWriteBack || state_ == State::kRefetch || (state_ == State::kFetch && !use_pf_) ||
                (g.idle && head && !g.head_hit && !g.pop);
  return g;
}

// How many ticks from now() on only count: no request, no pop, no state
// change, no cache change, no steal or clear, the FIFO's visible count the
// same. signals() would give each of them the same values, so run_until
// takes them at once.
uint64_t MemorySideTicks::counting_ticks(const Signals& g, uint64_t tick) const {
  if (clear_in_ || flush_in_ || steals_owed_ != 0 || clear_pending_) return 0;
  if (g.req || g.pop || g.miss_go || g.flush_step || g.wb_issue || g.pf_issue || g.cache_load || g.cache_write ||
      g.cache_invalidate || g.finishing)
    return 0;
  uint64_t k = tick - now_;
  switch (state_) {
    case State::kIdle:
    case State::kFlush:  // stays until `done` (finishing, excluded above) when its page is written back
      break;
    case State::kAccess:
    case State::kBlend:
      k = std::min(k, count_ - 1);  // the last tick writes the cache and moves on
      break;
    case State::kWriteBack:
    case State::kFetch:
      if (use_pf_) return 0;
      break;
    case State::kRefetch:
      if (!g.vbusy_o) return 0;
      break;
  }
  if (vbusy_) k = std::min(k, left_ - 1);  // the port's last tick finishes it
  if (steal_period_) k = std::min(k, steal_period_ - 1 - steal_count_);
  // A pixel pushed on tick t is seen from t + 1.
  if (seen_ < fifo_.size()) k = std::min(k, fifo_[seen_].tick + 1 - now_);
  return k;
}

// The memory quiet: no VRAM operation, request, steal, clear or flush under
// way or due, no write-behind write waiting, no prefetch. Then the HAD alone
// moves, and a pixel's ticks from its pop to its return to IDLE follow from
// hw/had's state machine in closed form (take_pixel). Most of a frame's
// pixels are taken so: stepped tick by tick, approx took 4.7x dda_bound's
// wall time.
[[gnu::always_inline]] inline bool MemorySideTicks::quiet() const {
  return !vbusy_ && steals_owed_ == 0 && !clear_in_ && !flush_in_ && !clear_pending_ && !flush_pending_ &&
         !wb_pending_ && !prefetch_ && state_ == State::kIdle;
}

// The FIFO's head, popped now when the memory is quiet and no steal comes
// due before the HAD is done with it (else false, nothing taken). On a hit
// the pop tick is the access's first; a miss writes the old page back when it
// must (one VRAM cycle; with write-behind that write goes on in the
// background: stepped), fetches (one more), then accesses; a blend adds its
// own ticks. The HAD is then held until its IDLE tick: the registers are
// already those of that tick; advance_held counts the ticks between.
[[gnu::always_inline]] inline bool MemorySideTicks::take_pixel(uint64_t in_fifo) {
  const Entry head = fifo_.front();
  const size_t slot = slot_of(head.page);
  const bool hit = valid_[slot] && page_[slot] == head.page;
  const bool write_back = !hit && valid_[slot] && (dirty_[slot] || !dirty_bits_);
  if (write_back && write_behind_) return false;
  const uint64_t vram_ticks = hit ? 0 : (write_back ? 2 : 1) * cycle_;
  const uint64_t access = hit ? (access_ <= 2 ? 1 : access_ - 1) : (access_ == 0 ? 1 : access_);
  const uint64_t blend = head.outcome == HadOutcome::kBlended ? blend_ : 0;
  const uint64_t ticks = 1 + vram_ticks + access + blend;
  // The edges of ticks now_ .. now_ + ticks - 1 must not raise a steal.
  if (steal_period_ && steal_count_ + ticks >= steal_period_) return false;
  fifo_max_ = std::max(fifo_max_, in_fifo);
  pix_ = head;
  popped(head);
  if (!hit) {
    ++page_misses_;
    if (on_miss_) on_miss_(head.page);
    valid_[slot] = true;
    page_[slot] = head.page;
    dirty_[slot] = false;
  }
  if (head.outcome == HadOutcome::kWritten || head.outcome == HadOutcome::kBlended) dirty_[slot] = true;
  held_pop_ = now_;
  held_until_ = now_ + ticks;
  held_vram_to_ = now_ + 1 + vram_ticks;  // waiting for the VRAM: the ticks after the pop, up to here
  return true;
}

[[gnu::always_inline]] inline void MemorySideTicks::advance_held(uint64_t tick) {
  const uint64_t to = std::min(tick, held_until_);
  busy_ticks_ += to - now_;
  const uint64_t wait_from = std::max(now_, held_pop_ + 1), wait_to = std::min(to, held_vram_to_);
  if (wait_to > wait_from) vram_wait_ticks_ += wait_to - wait_from;
  // No pop meanwhile: the FIFO's count is largest on the last tick (and at most what is pending).
  if (fifo_.size() > fifo_max_) fifo_max_ = std::max(fifo_max_, count_on(to - 1));
  if (steal_period_) steal_count_ += to - now_;
  now_ = to;
}

void MemorySideTicks::run(uint64_t tick) {
  while (now_ < tick) {
    if (now_ < held_until_) {
      advance_held(tick);
      continue;
    }
    if (quiet()) {
      const uint64_t in_fifo = fifo_count();
      if (in_fifo != 0 && take_pixel(in_fifo)) continue;
      if (in_fifo == 0 && (!steal_period_ || steal_count_ + 1 < steal_period_)) {
        // Waiting for the DDA: to the next pixel's arrival, or the tick before a steal comes due.
        uint64_t k = tick - now_;
        if (seen_ < fifo_.size()) k = std::min(k, fifo_[seen_].tick + 1 - now_);
        if (steal_period_) k = std::min(k, steal_period_ - 1 - steal_count_);
        now_ += k;
        if (steal_period_) steal_count_ += k;
        continue;
      }
    }
    const Signals g = signals();
    const uint64_t k = counting_ticks(g, tick);
    if (k == 0) {
      edge(g);
      continue;
    }
    now_ += k;
    if (steal_period_) steal_count_ += k;
    if (vbusy_) left_ -= k;
    if (state_ == State::kAccess || state_ == State::kBlend) count_ -= k;
    if (!g.idle) busy_ticks_ += k;
    if (g.vram_wait) vram_wait_ticks_ += k;
    fifo_max_ = std::max(fifo_max_, g.in_fifo);
  }
}

void MemorySideTicks::edge(const Signals& g) {
  fifo_max_ = std::max(fifo_max_, g.in_fifo);
  const Entry* head = g.head;
  const bool finishing = g.finishing, port_busy = g.port_busy, steal_due = g.steal_due, vbusy_o = g.vbusy_o,
             done = g.done, head_hit = g.head_hit, must_write_back = g.must_write_back, flush_valid = g.flush_valid,
             flush_write_back = g.flush_write_back, idle = g.idle, background_ok = g.background_ok,
             miss_go = g.miss_go, flush_step = g.flush_step, wb_issue = g.wb_issue, pf_issue = g.pf_issue,
             pop = g.pop, req = g.req, cache_load = g.cache_load, cache_write = g.cache_write,
             cache_invalidate = g.cache_invalidate;
  const size_t fslot = g.fslot;

  // ---- the clock edge: hw/vram ----
  const bool steal_comes_due = steal_period_ && steal_count_ + 1 >= steal_period_;
  if (steal_period_) steal_count_ = steal_comes_due ? 0 : steal_count_ + 1;
  steals_owed_ = steals_owed_ + unsigned(steal_comes_due && steals_owed_ != 0xFF) - unsigned(!port_busy && steal_due);
  if (vbusy_) --left_;
  if (finishing) vbusy_ = clearing_ = stealing_ = false;
  const bool clear_was_pending = clear_pending_ || clear_in_;
  if (clear_in_) clear_pending_ = true;
  if (!port_busy && steal_due) {  // a stolen cycle goes first
    vbusy_ = stealing_ = true;
    left_ = cycle_;
  } else if (!port_busy && clear_was_pending) {
    clear_pending_ = false;
    vbusy_ = clearing_ = true;
    left_ = clear_ticks_;
  } else if (!port_busy && req) {
    vbusy_ = true;
    left_ = cycle_;
  } else if (req) {
    throw std::logic_error("MemorySideTicks: a VRAM request while the port is busy");
  }

  // ---- the clock edge: the cache ----
  if (cache_invalidate) valid_[fslot] = false;
  if (cache_load) {
    const size_t s = slot_of(pix_.page);
    valid_[s] = true;
    page_[s] = pix_.page;
    dirty_[s] = false;
  } else if (cache_write) {
    dirty_[slot_of(pix_.page)] = true;
  }

  // ---- the clock edge: hw/had ----
  auto next_flush_slot = [&] {
    if (flush_slot_ + 1 == valid_.size()) {
      flush_slot_ = 0;
      flush_pending_ = false;
      pf_valid_ = false;
    } else {
      ++flush_slot_;
    }
  };
  if (flush_in_) flush_pending_ = true;
  if (wb_issue) wb_pending_ = false;
  const bool pf_arrives = pf_loading_ && done && background_ok;
  if (pf_issue) {
    pf_loading_ = true;
    pf_page_ = head->page;
  }
  if (pf_arrives) {
    pf_loading_ = false;
    pf_valid_ = true;
  }
  if (!idle || pop) ++busy_ticks_;
  if (g.vram_wait) ++vram_wait_ticks_;
  switch (state_) {
    case State::kIdle:
      if (pop) {
        pix_ = *head;
        popped(pix_);
      }
      if (pop && head_hit) {
        state_ = State::kAccess;  // the pop tick is the access's first
        count_ = access_ <= 2 ? 1 : access_ - 1;
      } else if (miss_go) {
        ++page_misses_;
        if (on_miss_) on_miss_(pix_.page);
        use_pf_ = pf_valid_ && pf_page_ == pix_.page;
        pf_valid_ = false;
        if (must_write_back && !write_behind_) {
          state_ = State::kWriteBack;
        } else {
          if (must_write_back) wb_pending_ = true;  // the old page waits in the write-behind register
          state_ = State::kFetch;
        }
      } else if (flush_step) {
        if (flush_valid) state_ = State::kFlush;
        else next_flush_slot();
      }
      break;
    case State::kWriteBack:
      if (done) state_ = use_pf_ || !vbusy_o ? State::kFetch : State::kRefetch;
      break;
    case State::kRefetch:
      if (!vbusy_o) state_ = State::kFetch;
      break;
    case State::kFetch:
      if (use_pf_ || done) {
        state_ = State::kAccess;
        use_pf_ = false;
        count_ = access_ == 0 ? 1 : access_;
      }
      break;
    case State::kAccess:
      if (count_ > 1) {
        --count_;
      } else if (pix_.outcome == HadOutcome::kBlended && blend_ > 0) {
        state_ = State::kBlend;
        count_ = blend_;
      } else {
        state_ = State::kIdle;
      }
      break;
    case State::kBlend:
      if (count_ > 1) --count_;
      else state_ = State::kIdle;
      break;
    case State::kFlush:
      if (done || !flush_write_back) {
        state_ = State::kIdle;
        next_flush_slot();
      }
      break;
  }
  clear_in_ = flush_in_ = false;
  ++now_;
}

}  // namespace girtd
