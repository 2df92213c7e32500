#include "had/memory_side_ticks.hpp"

#include <algorithm>
#include <stdexcept>

#include "layout/rtl_layout.hpp"

namespace girtd {

MemorySideTicks::MemorySideTicks(const Params& p)
    : access_(uint64_t(p.ticks(p.had_access_ns))),
      blend_(uint64_t(p.ticks(p.had_blend_extra_ns))),
      write_behind_(p.had_write_behind),
      prefetch_(p.had_prefetch),
      cache_(rtl_layout(p).cache, p.had_dirty_bits),
      vram_(p) {}

[[gnu::always_inline]] inline void MemorySideTicks::pop_head() {
  pix_ = fifo_.head();
  fifo_.pop(now_);
}

bool MemorySideTicks::idle() const {
  return now_ >= held_until_ && state_ == State::kIdle && !flush_pending_ && !wb_pending_ && !pf_loading_ &&
         fifo_.empty() && !vram_.busy();
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
  // ---- this tick's signals, from the registers (hw/had; hw/vram's are vram_'s) ----
  Signals g;
  g.in_fifo = fifo_.count(now_);
  const FifoPixel* head = g.in_fifo ? &fifo_.head() : nullptr;
  g.head = head;
  g.vbusy_o = vram_.busy();
  g.done = vram_.done();

  const size_t hslot = head ? cache_.slot_of(head->page) : 0;
  const bool victim_valid = head && cache_.valid(hslot);
  g.head_hit = head && cache_.holds(hslot, head->page);
  g.must_write_back = head && cache_.must_write_back(hslot);
  const bool head_in_pf = head && pf_page_ == head->page && (pf_valid_ || pf_loading_);
  g.fslot = flush_slot_;
  g.flush_valid = cache_.valid(g.fslot);
  g.flush_write_back = cache_.must_write_back(g.fslot);
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
  if (clear_in_ || flush_in_ || vram_.claimed()) return 0;
  if (g.req || g.pop || g.miss_go || g.flush_step || g.wb_issue || g.pf_issue || g.cache_load || g.cache_write ||
      g.cache_invalidate || vram_.finishing())
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
  k = vram_.counting_ticks(k);  // the port's last tick finishes it; a steal comes due
  // A pixel pushed on tick t is seen from t + 1.
  return std::min(k, fifo_.next_arrival() - now_);
}

// The memory quiet: no VRAM operation, request, steal, clear or flush under
// way or due, no write-behind write waiting, no prefetch. Then the HAD alone
// moves, and a pixel's ticks from its pop to its return to IDLE follow from
// hw/had's state machine in closed form (take_pixel). Most of a frame's
// pixels are taken so: stepped tick by tick, approx took 4.7x dda_bound's
// wall time.
[[gnu::always_inline]] inline bool MemorySideTicks::quiet() const {
  return vram_.quiet() && !clear_in_ && !flush_in_ && !flush_pending_ && !wb_pending_ && !prefetch_ &&
         state_ == State::kIdle;
}

// The FIFO's head, popped now when the memory is quiet and no steal comes
// due before the HAD is done with it (else false, nothing taken). On a hit
// the pop tick is the access's first; a miss writes the old page back when it
// must (one VRAM cycle; with write-behind that write goes on in the
// background: stepped), fetches (one more), then accesses; a blend adds its
// own ticks. The HAD is then held until its IDLE tick: the registers are
// already those of that tick; advance_held counts the ticks between.
[[gnu::always_inline]] inline bool MemorySideTicks::take_pixel(uint64_t in_fifo) {
  const FifoPixel head = fifo_.head();  // a copy: pop_head() frees its slot
  const size_t slot = cache_.slot_of(head.page);
  const bool hit = cache_.holds(slot, head.page);
  const bool write_back = !hit && cache_.must_write_back(slot);
  if (write_back && write_behind_) return false;
  const uint64_t vram_ticks = hit ? 0 : (write_back ? 2 : 1) * vram_.cycle();
  const uint64_t access = hit ? (access_ <= 2 ? 1 : access_ - 1) : (access_ == 0 ? 1 : access_);
  const uint64_t blend = head.outcome == HadOutcome::kBlended ? blend_ : 0;
  const uint64_t ticks = 1 + vram_ticks + access + blend;
  // The edges of ticks now_ .. now_ + ticks - 1 must not raise a steal.
  if (vram_.steal_within(ticks)) return false;
  fifo_.note_count(in_fifo);
  pop_head();
  if (!hit) {
    ++page_misses_;
    if (on_miss_) on_miss_(pix_.page);
    cache_.load(slot, pix_.page);
  }
  if (pix_.outcome == HadOutcome::kWritten || pix_.outcome == HadOutcome::kBlended) cache_.write(slot);
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
  if (fifo_.pending() > fifo_.max()) fifo_.note_count(fifo_.count_on(to - 1));
  vram_.count(to - now_);  // quiet: only the steal counter
  now_ = to;
}

void MemorySideTicks::run(uint64_t tick) {
  while (now_ < tick) {
    if (now_ < held_until_) {
      advance_held(tick);
      continue;
    }
    if (quiet()) {
      const uint64_t in_fifo = fifo_.count(now_);
      if (in_fifo != 0 && take_pixel(in_fifo)) continue;
      if (in_fifo == 0 && !vram_.steal_within(1)) {
        // Waiting for the DDA: to the next pixel's arrival, or the tick before a steal comes due.
        const uint64_t k = vram_.counting_ticks(std::min(tick, fifo_.next_arrival()) - now_);
        now_ += k;
        vram_.count(k);
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
    vram_.count(k);
    if (state_ == State::kAccess || state_ == State::kBlend) count_ -= k;
    if (!g.idle) busy_ticks_ += k;
    if (g.vram_wait) vram_wait_ticks_ += k;
    fifo_.note_count(g.in_fifo);
  }
}

void MemorySideTicks::edge(const Signals& g) {
  fifo_.note_count(g.in_fifo);
  const FifoPixel* head = g.head;

  // ---- the clock edge: hw/vram ----
  vram_.edge(g.req, clear_in_);

  // ---- the clock edge: the cache ----
  if (g.cache_invalidate) cache_.invalidate(g.fslot);
  if (g.cache_load) cache_.load(cache_.slot_of(pix_.page), pix_.page);
  else if (g.cache_write) cache_.write(cache_.slot_of(pix_.page));

  // ---- the clock edge: hw/had ----
  auto next_flush_slot = [&] {
    if (flush_slot_ + 1 == cache_.slots()) {
      flush_slot_ = 0;
      flush_pending_ = false;
      pf_valid_ = false;
    } else {
      ++flush_slot_;
    }
  };
  if (flush_in_) flush_pending_ = true;
  if (g.wb_issue) wb_pending_ = false;
  const bool pf_arrives = pf_loading_ && g.done && g.background_ok;
  if (g.pf_issue) {
    pf_loading_ = true;
    pf_page_ = head->page;
  }
  if (pf_arrives) {
    pf_loading_ = false;
    pf_valid_ = true;
  }
  if (!g.idle || g.pop) ++busy_ticks_;
  if (g.vram_wait) ++vram_wait_ticks_;
  switch (state_) {
    case State::kIdle:
      if (g.pop) pop_head();
      if (g.pop && g.head_hit) {
        state_ = State::kAccess;  // the pop tick is the access's first
        count_ = access_ <= 2 ? 1 : access_ - 1;
      } else if (g.miss_go) {
        ++page_misses_;
        if (on_miss_) on_miss_(pix_.page);
        use_pf_ = pf_valid_ && pf_page_ == pix_.page;
        pf_valid_ = false;
        if (g.must_write_back && !write_behind_) {
          state_ = State::kWriteBack;
        } else {
          if (g.must_write_back) wb_pending_ = true;  // the old page waits in the write-behind register
          state_ = State::kFetch;
        }
      } else if (g.flush_step) {
        if (g.flush_valid) state_ = State::kFlush;
        else next_flush_slot();
      }
      break;
    case State::kWriteBack:
      if (g.done) state_ = use_pf_ || !g.vbusy_o ? State::kFetch : State::kRefetch;
      break;
    case State::kRefetch:
      if (!g.vbusy_o) state_ = State::kFetch;
      break;
    case State::kFetch:
      if (use_pf_ || g.done) {
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
      if (g.done || !g.flush_write_back) {
        state_ = State::kIdle;
        next_flush_slot();
      }
      break;
  }
  clear_in_ = flush_in_ = false;
  ++now_;
}

}  // namespace girtd
