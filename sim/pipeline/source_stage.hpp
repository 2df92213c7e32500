// The pipeline's input: the trace's frames, item by item, as fast as the
// first FIFO takes them (the database is not modeled).
#pragma once

#include <systemc>

#include <vector>

#include "timeline/stage_activity.hpp"
#include "pipeline/token.hpp"

namespace girtd {

template <typename T>
class SourceStage : public sc_core::sc_module {
 public:
  sc_core::sc_fifo_out<Token<T>> out;

  SC_HAS_PROCESS(SourceStage);
  // `frames` must outlive the simulation.
  SourceStage(const sc_core::sc_module_name& name, const std::vector<std::vector<T>>& frames, FifoActivity& out_fifo)
      : sc_module(name), frames_(frames), out_fifo_(out_fifo) {
    SC_THREAD(run);
  }

 private:
  void put(const Token<T>& t) {
    out.write(t);
    out_fifo_.push(sc_core::sc_time_stamp().to_seconds());
  }
  void run() {
    for (size_t f = 0; f < frames_.size(); ++f) {
      put({TokenKind::kFrameBegin, f, {}});
      for (const T& item : frames_[f]) put({TokenKind::kItem, f, item});
      put({TokenKind::kFrameEnd, f, {}});
    }
    put({TokenKind::kEnd, frames_.size(), {}});
  }

  const std::vector<std::vector<T>>& frames_;
  FifoActivity& out_fifo_;
};

}  // namespace girtd
