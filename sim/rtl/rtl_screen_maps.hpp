// report.html's heat maps on rtl, from what the RTL shows at its edges: the
// pixels its DDA pushes, in order, and its DDA clock counter. A triangle's
// last pixels can still be in the DDA's output stages when it takes the next
// parameter set (dda.output_latency_clocks >= 2, or a stall): that many of
// the pushes after the load are still its own.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <stdexcept>

#include "backends/screen_maps.hpp"

namespace girtd {

class RtlScreenMaps {
 public:
  explicit RtlScreenMaps(const Params& p) : rec_(p) {}
  void begin_frame() { rec_.begin_frame(); }
  // The DDA takes a parameter set at this edge, its clock counter at
  // `dda_clocks`; `in_flight` pixels are in its output stages (one of them
  // may be pushed at this very edge, after this call).
  void loaded(uint64_t dda_clocks, uint64_t in_flight) {
    close_open(dda_clocks, in_flight);
    open_ = Triangle{dda_clocks, 0, 0};
  }
  // A pixel the DDA pushes into the FIFO: the oldest triangle still owed
  // pixels gets it, else the one being drawn.
  void pushed(int x, int y) {
    rec_.pixel(x, y);
    if (finishing_.empty()) {
      if (open_) ++open_->pixels;
      return;
    }
    ++finishing_.front().pixels;
    --finishing_.front().pending;
    end_finished();
  }
  // Everything pushed and the DDA idle: the triangle drawn last is done.
  void idle(uint64_t dda_clocks) { close_open(dda_clocks, 0); }
  const ScreenMaps& maps() const { return rec_.maps(); }

 private:
  struct Triangle {
    uint64_t clocks;   // while open: the counter at its load; once closed: its clocks
    uint64_t pixels;   // pushed so far
    uint64_t pending;  // pushes still its own once closed
  };
  void close_open(uint64_t dda_clocks, uint64_t in_flight) {
    if (!open_) return;
    uint64_t owed = 0;  // to triangles before it: their pixels leave first
    for (const Triangle& t : finishing_) owed += t.pending;
    if (in_flight < owed) throw std::logic_error("RTL heat maps: fewer pixels in the DDA's output stages than owed");
    finishing_.push_back({dda_clocks - open_->clocks, open_->pixels, in_flight - owed});
    open_.reset();
    end_finished();
  }
  void end_finished() {
    while (!finishing_.empty() && finishing_.front().pending == 0) {
      rec_.end_triangle(finishing_.front().clocks, finishing_.front().pixels);
      finishing_.pop_front();
    }
  }

  ScreenMapRecorder rec_;
  std::optional<Triangle> open_;  // the triangle the DDA is drawing
  std::deque<Triangle> finishing_;
};

}  // namespace girtd
