// One front-end stage (or the preparer) as a SystemC module: it takes a
// token from its input FIFO, lets its model say what work that is (a list of
// steps: so many flops, then optionally an item out), spends each step's
// flops at the stage's rate and writes the item on. Frame markers pass
// through; a stage that holds a whole frame does its work at the closing one.
// Starved (input empty), busy and blocked (output full) time are counted.
#pragma once

#include <systemc>

#include <functional>
#include <optional>
#include <vector>

#include "timeline/stage_activity.hpp"
#include "pipeline/token.hpp"

namespace girtd {

template <typename Out>
struct WorkStep {
  double flops = 0;
  std::optional<Out> out;  // handed on once the flops are spent
};

template <typename Out>
using Work = std::vector<WorkStep<Out>>;

template <typename In, typename Out>
class TimedStage : public sc_core::sc_module {
 public:
  using ItemFn = std::function<void(size_t frame, const In&, Work<Out>&)>;
  using FrameFn = std::function<void(size_t frame, Work<Out>&)>;

  sc_core::sc_fifo_in<Token<In>> in;
  sc_core::sc_fifo_out<Token<Out>> out;

  SC_HAS_PROCESS(TimedStage);
  // `in_fifo`, `out_fifo`: the occupancy records of the FIFOs `in` reads and `out` writes.
  TimedStage(const sc_core::sc_module_name& name, double flops_per_s, ItemFn on_item, FrameFn on_begin,
             FrameFn on_end, StageActivity& activity, FifoActivity& in_fifo, FifoActivity& out_fifo)
      : sc_module(name), rate_(flops_per_s), on_item_(std::move(on_item)), on_begin_(std::move(on_begin)),
        on_end_(std::move(on_end)), a_(activity), in_fifo_(in_fifo), out_fifo_(out_fifo) {
    SC_THREAD(run);
  }

 private:
  void run() {
    for (;;) {
      const sc_core::sc_time t0 = sc_core::sc_time_stamp();
      a_.state = StageState::kStarved;
      const Token<In> tok = in.read();
      a_.state = StageState::kBusy;
      const double now = sc_core::sc_time_stamp().to_seconds();
      in_fifo_.pop(now);
      a_.starved_s += now - t0.to_seconds();
      if (series_) a_.series.add_span(size_t(StageState::kStarved), t0.to_seconds(), now);
      work_.clear();
      switch (tok.kind) {
        case TokenKind::kItem:
          ++a_.items;
          on_item_(tok.frame, tok.item, work_);
          perform(tok.frame);
          break;
        case TokenKind::kFrameBegin:
          a_.frame_begin_s.push_back(sc_core::sc_time_stamp().to_seconds());
          if (on_begin_) on_begin_(tok.frame, work_);
          write(Token<Out>{TokenKind::kFrameBegin, tok.frame, {}});
          perform(tok.frame);
          break;
        case TokenKind::kFrameEnd:
          if (on_end_) on_end_(tok.frame, work_);
          perform(tok.frame);
          write(Token<Out>{TokenKind::kFrameEnd, tok.frame, {}});
          a_.frame_end_s.push_back(sc_core::sc_time_stamp().to_seconds());
          break;
        case TokenKind::kEnd:
          write(Token<Out>{TokenKind::kEnd, tok.frame, {}});
          return;
      }
    }
  }

  void perform(size_t frame) {
    for (WorkStep<Out>& s : work_) {
      if (s.flops > 0) {
        const double busy = s.flops / rate_;
        a_.flops += s.flops;
        a_.busy_s += busy;
        const double from = sc_core::sc_time_stamp().to_seconds();
        wait(sc_core::sc_time(busy, sc_core::SC_SEC));
        if (series_) a_.series.add_span(size_t(StageState::kBusy), from, sc_core::sc_time_stamp().to_seconds());
      }
      if (s.out) {
        ++a_.emitted;
        write(Token<Out>{TokenKind::kItem, frame, std::move(*s.out)});
      }
    }
  }

  void write(const Token<Out>& t) {
    const sc_core::sc_time t0 = sc_core::sc_time_stamp();
    a_.state = StageState::kBlocked;
    out.write(t);
    a_.state = StageState::kBusy;
    const double now = sc_core::sc_time_stamp().to_seconds();
    out_fifo_.push(now);
    a_.blocked_s += now - t0.to_seconds();
    if (series_) a_.series.add_span(size_t(StageState::kBlocked), t0.to_seconds(), now);
  }

  bool series_ = record_series();
  double rate_;
  ItemFn on_item_;
  FrameFn on_begin_, on_end_;
  StageActivity& a_;
  FifoActivity& in_fifo_;
  FifoActivity& out_fifo_;
  Work<Out> work_;
};

}  // namespace girtd
