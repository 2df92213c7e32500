// The pipeline's input: the frames, item by item, as fast as the first FIFO
// takes them (the database is not modeled). A frame's items are asked for
// when the stage reaches it, so frames are made as the run goes.
#pragma once

#include <systemc>

#include <functional>
#include <vector>

#include "timeline/stage_activity.hpp"
#include "pipeline/token.hpp"

namespace girtd {

template <typename T>
class SourceStage : public sc_core::sc_module {
 public:
  sc_core::sc_fifo_out<Token<T>> out;

  // Frame f's items, asked for once each frame, in order.
  using FrameItems = std::function<std::vector<T>(size_t f)>;

  SC_HAS_PROCESS(SourceStage);
  SourceStage(const sc_core::sc_module_name& name, size_t frames, FrameItems items, FifoActivity& out_fifo)
      : sc_module(name), frames_(frames), items_(std::move(items)), out_fifo_(out_fifo) {
    SC_THREAD(run);
  }

 private:
  void put(const Token<T>& t) {
    out.write(t);
    out_fifo_.push(sc_core::sc_time_stamp().to_seconds());
  }
  void run() {
    for (size_t f = 0; f < frames_; ++f) {
      const std::vector<T> items = items_(f);
      put({TokenKind::kFrameBegin, f, {}});
      for (const T& item : items) put({TokenKind::kItem, f, item});
      put({TokenKind::kFrameEnd, f, {}});
    }
    put({TokenKind::kEnd, frames_, {}});
  }

  size_t frames_;
  FrameItems items_;
  FifoActivity& out_fifo_;
};

}  // namespace girtd
