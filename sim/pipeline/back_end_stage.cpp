#include "pipeline/back_end_stage.hpp"

#include <cmath>

namespace girtd {

using sc_core::sc_time;
using sc_core::sc_time_stamp;

BackEndStage::BackEndStage(const sc_core::sc_module_name& name, BackEndEngine& engine,
                           const std::vector<FrameSettings>& frames, double tick_ns, StageActivity& activity,
                           FifoActivity& in_fifo, FrameDone frame_done, Progress progress)
    : sc_module(name), engine_(engine), frames_(frames), tick_ns_(tick_ns), a_(activity), in_fifo_(in_fifo),
      frame_done_(std::move(frame_done)), progress_(std::move(progress)) {
  SC_THREAD(run);
}

sc_time BackEndStage::at(uint64_t tick) const { return sc_time(static_cast<double>(tick) * tick_ns_, sc_core::SC_NS); }

uint64_t BackEndStage::tick_of(const sc_time& t) const {
  return static_cast<uint64_t>(std::ceil(t.to_seconds() * 1e9 / tick_ns_ - 1e-6));
}

void BackEndStage::sync_to(uint64_t tick) {
  const sc_time t = at(tick);
  if (t > sc_time_stamp()) wait(t - sc_time_stamp());
}

void BackEndStage::run() {
  uint64_t triangles = 0;
  for (;;) {
    const uint64_t before = engine_.now_tick();  // the run's end, if the next token is the last
    sync_to(engine_.ready_tick());
    Token<DdaParams> tok;
    if (!in.nb_read(tok)) {
      const sc_time t0 = sc_time_stamp();
      tok = in.read();
      a_.starved_s += (sc_time_stamp() - t0).to_seconds();
      engine_.idle_until(tick_of(sc_time_stamp()));
    }
    in_fifo_.pop();
    switch (tok.kind) {
      case TokenKind::kFrameBegin:
        engine_.begin_frame(frames_.at(tok.frame));
        break;
      case TokenKind::kItem:
        ++a_.items;
        engine_.draw(tok.item);
        if (progress_ && (++triangles & 15) == 0) progress_(tok.frame, triangles, at(engine_.now_tick()).to_seconds());
        break;
      case TokenKind::kFrameEnd:
        engine_.end_frame();
        if (frame_done_) frame_done_(tok.frame);
        break;
      case TokenKind::kEnd:
        end_tick_ = before;  // not the wait for a DDA clock that no parameter set needed
        finished_ = true;
        return;
    }
  }
}

}  // namespace girtd
