// The memory side of GIRTD's back end (FIFO -> HAD + cache -> VRAM), as
// hw/had clocks it: its state machine over the FIFO (sim/fifo), the cache's
// tags (sim/cache) and the VRAM port (sim/vram), without their data (a
// page number, valid and dirty per cache slot; a pixel's page and what the
// HAD does with it), with every option the RTL has (write-behind, prefetch,
// dirty bits, stolen VRAM cycles, page shapes, cache sizes). State n is the
// registers after n ticks; signals() evaluates state n and edge() takes
// the clock edge, as the RTL does. Ticks on which only counters move are
// taken at once, and so is a whole pixel while the memory is quiet
// (take_pixel): the answer is the RTL's to the tick either way.
#pragma once

#include <cstdint>
#include <functional>

#include "cache/cache_tags.hpp"
#include "config/params.hpp"
#include "fifo/pixel_fifo_ticks.hpp"
#include "had/had.hpp"
#include "vram/vram_port_ticks.hpp"

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
  void push(uint32_t page, HadOutcome outcome, uint64_t tick) { fifo_.push(tick, page, outcome, now_); }
  // Pixels pushed before now() and not yet popped: the FIFO's count at now().
  uint64_t fifo_count() const { return fifo_.count(now_); }
  // Pixels pushed and not yet popped, those the memory side has not reached included.
  uint64_t pending() const { return fifo_.pending(); }
  // The HAD idle with nothing pending and the VRAM free, at now() (the
  // back end's idle but for the DDA).
  bool idle() const;
  void clear();  // the frame clear is requested on this tick
  void flush();  // the frame-end flush is requested on this tick

  uint64_t page_misses() const { return page_misses_; }
  uint64_t busy_ticks() const { return busy_ticks_; }
  uint64_t vram_wait_ticks() const { return vram_wait_ticks_; }
  uint64_t fifo_max() const { return fifo_.max(); }
  // Each pixel's stay in the FIFO, in push order, in batches: when a batch
  // fills, and at tell_fifo_stays().
  void on_fifo_stays(PixelFifoTicks::StaysListener f) { fifo_.on_stays(std::move(f)); }
  void tell_fifo_stays() { fifo_.tell_stays(); }
  void on_page_miss(std::function<void(uint32_t page)> f) { on_miss_ = std::move(f); }

 private:
  enum class State { kIdle, kWriteBack, kFetch, kAccess, kBlend, kFlush, kRefetch };
  // One tick's combinational signals, evaluated from the registers.
  struct Signals {
    uint64_t in_fifo = 0;
    const FifoPixel* head = nullptr;
    bool vbusy_o, done, head_hit, must_write_back, flush_valid, flush_write_back, idle, background_ok, miss_go,
        flush_step, wb_issue, pf_issue, pop, req, cache_load, cache_write, cache_invalidate, vram_wait;
    size_t fslot = 0;
  };
  Signals signals() const;
  void edge(const Signals& g);  // the clock edge: state n -> n + 1
  // Ticks from now() (up to `tick`) on which nothing but counters moves:
  // run() takes them at once.
  uint64_t counting_ticks(const Signals& g, uint64_t tick) const;
  bool quiet() const;
  void run(uint64_t tick);
  bool take_pixel(uint64_t in_fifo);  // the FIFO's count now
  void advance_held(uint64_t tick);
  void pop_head();  // the FIFO's head into pix_, now

  const uint64_t access_, blend_;
  const bool write_behind_, prefetch_;
  uint64_t now_ = 0;
  // A pixel taken whole (take_pixel): popped on held_pop_, waiting for the
  // VRAM before held_vram_to_, the HAD IDLE again on held_until_.
  uint64_t held_pop_ = 0, held_vram_to_ = 0, held_until_ = 0;
  PixelFifoTicks fifo_;
  CacheTags cache_;
  VramPortTicks vram_;
  bool clear_in_ = false, flush_in_ = false;  // this tick's requests
  // hw/had's registers
  State state_ = State::kIdle;
  uint64_t count_ = 0;
  FifoPixel pix_{};
  bool flush_pending_ = false, wb_pending_ = false, pf_valid_ = false, pf_loading_ = false, use_pf_ = false;
  uint32_t pf_page_ = 0;
  size_t flush_slot_ = 0;
  // counters, as the RTL's
  uint64_t page_misses_ = 0, busy_ticks_ = 0, vram_wait_ticks_ = 0;
  std::function<void(uint32_t)> on_miss_;
};

}  // namespace girtd
