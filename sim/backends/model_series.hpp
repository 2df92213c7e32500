// report.html's series from approx's timing model (sim/dda, sim/had): the
// DDA -> HAD FIFO's occupancy and the two heat maps, fed pixel by pixel as
// the golden DDA draws. One piece for the approx back end and for the
// [timing] tests that check it against the RTL's.
#pragma once

#include <cstdint>

#include "fifo/fifo_levels.hpp"
#include "backends/screen_maps.hpp"
#include "dda/dda_timing.hpp"

namespace girtd {

class ModelSeries {
 public:
  // `model` must outlive this; this registers itself with it.
  ModelSeries(const Params& p, BackendTimingModel& model)
      : fifo_(p.base_tick_ns * 1e-9), maps_(p) {
    model.on_fifo_stays([this](const std::vector<PixelFifoTicks::Stay>& stays) {
      for (const PixelFifoTicks::Stay& s : stays) fifo_.interval(s.push, s.pop);
    });
    model.on_page_miss([this](uint32_t page) { maps_.page_missed(page); });
  }
  ModelSeries(const ModelSeries&) = delete;
  ModelSeries& operator=(const ModelSeries&) = delete;

  void begin_frame() { maps_.begin_frame(); }
  // After model.pixel() for the pixel at (x, y) (its FIFO push the model watches).
  void pixel(int x, int y) { maps_.drawn(x, y); }
  // After model.pixel() for each pixel of a run along row y, x_a to x_b.
  void run(int y, int x_a, int x_b) {
    maps_.drawn(x_a, y);
    maps_.drawn(x_b, y);
  }
  void end_triangle(uint64_t dda_cycles, uint64_t emitted) { maps_.end_triangle(dda_cycles, emitted); }

  // Complete once the model has drained (a pixel's stay is told once it has left the FIFO).
  FifoSeries fifo(uint64_t end) const { return fifo_.series(end); }
  const ScreenMaps& maps() const { return maps_.maps(); }

 private:
  FifoLevels fifo_;
  ScreenMapRecorder maps_;
};

}  // namespace girtd
