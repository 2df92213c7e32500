// The memory side of GIRTD's back end (FIFO -> HAD + cache -> VRAM), as
// hw/had, hw/cache and hw/vram clock it: their registers and decisions
// without their data (a page number, valid and dirty per cache slot; a
// pixel's page and what the HAD does with it), with every option the RTL
// has (write-behind, prefetch, dirty bits, stolen VRAM cycles, page shapes,
// cache sizes). State n is the registers after n ticks; signals() evaluates
// state n and edge() takes the clock edge, as the RTL does. Ticks on which
// only counters move are taken at once, and so is a whole pixel while the
// memory is quiet (take_pixel): the answer is the RTL's to the tick either way.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "common/block_queue.hpp"
#include "config/params.hpp"
#include "layout/rtl_layout.hpp"
#include "had/had.hpp"

namespace girtd {

class MemorySideTicks {
 public:
  explicit MemorySideTicks(const Params& p);

  uint64_t now() const { return now_; }
  // Steps until now() == tick (no-op when already there or past).
  void run_until(uint64_t tick) {
    if (now_ < tick) run(tick);
  }
  // While a pixel is taken whole: the tick the HAD is IDLE again; it pops
  // nothing before. Stale (at or before now()) once that tick is reached.
  uint64_t held_until() const { return held_until_; }
  // The DDA pushes a pixel of `page` on tick `tick` (at or after now() and
  // after the last push; the memory side need not have reached it): it is
  // in the FIFO from the next tick on.
  void push(uint32_t page, HadOutcome outcome, uint64_t tick);
  // Pixels pushed before now() and not yet popped: the FIFO's count at now().
  uint64_t fifo_count() const {
    while (seen_ < fifo_.size() && fifo_[seen_].tick < now_) ++seen_;
    return seen_;
  }
  // Pixels pushed and not yet popped, those the memory side has not reached included.
  uint64_t pending() const { return fifo_.size(); }
  // The HAD idle with nothing pending and the VRAM free, at now() (the
  // back end's idle but for the DDA).
  bool idle() const;
  void clear();  // the frame clear is requested on this tick
  void flush();  // the frame-end flush is requested on this tick

  uint64_t page_misses() const { return page_misses_; }
  uint64_t busy_ticks() const { return busy_ticks_; }
  uint64_t vram_wait_ticks() const { return vram_wait_ticks_; }
  uint64_t fifo_max() const { return fifo_max_; }
  // Each pixel's stay in the FIFO: the ticks it was pushed and popped on.
  // Told in push order, in batches (a call per pixel cost more than the
  // series it feeds): when a batch fills, and at tell_fifo_stays().
  struct FifoStay {
    uint64_t push, pop;
  };
  using StaysListener = std::function<void(const std::vector<FifoStay>&)>;
  void on_fifo_stays(StaysListener f) { on_stays_ = std::move(f); }
  void tell_fifo_stays();
  void on_page_miss(std::function<void(uint32_t page)> f) { on_miss_ = std::move(f); }

 private:
  static constexpr size_t kStaysBatch = 4096;
  enum class State { kIdle, kWriteBack, kFetch, kAccess, kBlend, kFlush, kRefetch };
  struct Entry {
    uint64_t tick;  // pushed on
    uint32_t page;
    HadOutcome outcome;
  };
  // One tick's combinational signals, evaluated from the registers.
  struct Signals {
    uint64_t in_fifo = 0;
    const Entry* head = nullptr;
    bool finishing, port_busy, steal_due, vbusy_o, done, head_hit, must_write_back, flush_valid, flush_write_back,
        idle, background_ok, miss_go, flush_step, wb_issue, pf_issue, pop, req, cache_load, cache_write,
        cache_invalidate, vram_wait;
    size_t fslot = 0;
  };
  Signals signals() const;
  void edge(const Signals& g);  // the clock edge: state n -> n + 1
  // Ticks from now() (up to `tick`) on which nothing but counters moves:
  // run() takes them at once.
  uint64_t counting_ticks(const Signals& g, uint64_t tick) const;
  bool vram_busy() const;
  bool quiet() const;
  void run(uint64_t tick);
  bool take_pixel(uint64_t in_fifo);  // the FIFO's count now
  void advance_held(uint64_t tick);
  size_t slot_of(uint32_t page) const { return size_t(layout_.cache.slot_of(page)); }
  void popped(const Entry& e);  // the FIFO's head leaves it now
  uint64_t count_on(uint64_t tick) const;  // the FIFO's count on `tick` (at or after now_, no pop between)

  const RtlLayout layout_;
  const uint64_t access_, blend_, cycle_, clear_ticks_, steal_period_;
  const bool write_behind_, prefetch_, dirty_bits_;
  uint64_t now_ = 0;
  // A pixel taken whole (take_pixel): popped on held_pop_, waiting for the
  // VRAM before held_vram_to_, the HAD IDLE again on held_until_.
  uint64_t held_pop_ = 0, held_vram_to_ = 0, held_until_ = 0;
  BlockQueue<Entry> fifo_;
  mutable size_t seen_ = 0;  // fifo_'s first entries, pushed before now_ (the FIFO's count)
  bool clear_in_ = false, flush_in_ = false;  // this tick's requests
  // hw/vram
  bool vbusy_ = false, clearing_ = false, stealing_ = false, clear_pending_ = false;
  uint64_t left_ = 0, steal_count_ = 0;
  unsigned steals_owed_ = 0;
  // hw/had and its cache
  State state_ = State::kIdle;
  uint64_t count_ = 0;
  Entry pix_{};
  bool flush_pending_ = false, wb_pending_ = false, pf_valid_ = false, pf_loading_ = false, use_pf_ = false;
  uint32_t pf_page_ = 0;
  size_t flush_slot_ = 0;
  std::vector<uint8_t> valid_, dirty_;  // bytes, not std::vector<bool>'s bits: read on every pixel
  std::vector<uint32_t> page_;
  // counters, as the RTL's
  uint64_t page_misses_ = 0, busy_ticks_ = 0, vram_wait_ticks_ = 0, fifo_max_ = 0;
  StaysListener on_stays_;
  std::vector<FifoStay> stays_;  // popped, not yet told
  std::function<void(uint32_t)> on_miss_;
};

}  // namespace girtd
