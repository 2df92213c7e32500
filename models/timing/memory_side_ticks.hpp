// The memory side of GIRTD's back end (FIFO -> HAD + cache -> VRAM) stepped
// tick by tick: hw/had, hw/pixel_cache and hw/vram's registers and
// decisions without their data (a page number, valid and dirty per cache
// slot; a pixel's page and what the HAD does with it). The event model
// (backend_timing.*) computes a pixel's times when it is pushed; with
// prefetch the HAD acts on whichever pixel is at the FIFO's head on each
// tick, and with stolen VRAM cycles the port follows a free-running counter,
// so those two options are stepped here, like the RTL, tick for tick.
// State n is the registers after n ticks; signals() evaluates state n and
// edge() takes the clock edge, as the RTL does.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <vector>

#include "config/params.hpp"
#include "layout/rtl_layout.hpp"
#include "had/had.hpp"

namespace girtd {

class MemorySideTicks {
 public:
  explicit MemorySideTicks(const Params& p);

  uint64_t now() const { return now_; }
  // Steps until now() == tick (no-op when already there or past).
  void run_until(uint64_t tick);
  // The DDA pushes a pixel of `page` on tick `tick` (== now(): run_until it
  // first): it is in the FIFO from the next tick on.
  void push(uint32_t page, HadOutcome outcome, uint64_t tick);
  // Pixels pushed before now() and not yet popped: the FIFO's count at now().
  uint64_t fifo_count() const { return fifo_.size() - (!fifo_.empty() && fifo_.back().tick >= now_ ? 1 : 0); }
  // The HAD idle with nothing pending and the VRAM free, at now() (the
  // back end's idle but for the DDA).
  bool idle() const;
  void clear();  // the frame clear is requested on this tick
  void flush();  // the frame-end flush is requested on this tick

  uint64_t page_misses() const { return page_misses_; }
  uint64_t busy_ticks() const { return busy_ticks_; }
  uint64_t vram_wait_ticks() const { return vram_wait_ticks_; }
  uint64_t fifo_max() const { return fifo_max_; }
  // Called as each pixel leaves the FIFO: the ticks it was pushed and popped on.
  void on_pop(std::function<void(uint64_t push, uint64_t pop)> f) { on_pop_ = std::move(f); }
  void on_page_miss(std::function<void(uint32_t page)> f) { on_miss_ = std::move(f); }

 private:
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
  // run_until takes them at once.
  uint64_t counting_ticks(const Signals& g, uint64_t tick) const;
  bool vram_busy() const;
  size_t slot_of(uint32_t page) const { return size_t(layout_.cache.slot_of(page)); }
  void start_vram();  // an operation of cycle_ length

  const RtlLayout layout_;
  const uint64_t access_, blend_, cycle_, clear_ticks_, steal_period_;
  const bool write_behind_, prefetch_, dirty_bits_;
  uint64_t now_ = 0;
  std::deque<Entry> fifo_;
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
  std::vector<bool> valid_, dirty_;
  std::vector<uint32_t> page_;
  // counters, as the RTL's
  uint64_t page_misses_ = 0, busy_ticks_ = 0, vram_wait_ticks_ = 0, fifo_max_ = 0;
  std::function<void(uint64_t, uint64_t)> on_pop_;
  std::function<void(uint32_t)> on_miss_;
};

}  // namespace girtd
