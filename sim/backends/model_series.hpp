// report.html's series from approx's event model (models/timing): the
// DDA -> HAD FIFO's occupancy and the two heat maps, fed pixel by pixel as
// the golden DDA draws. One piece for the approx back end and for the
// [timing] tests that check it against the RTL's.
#pragma once

#include <cstdint>

#include "backends/fifo_levels.hpp"
#include "backends/screen_maps.hpp"
#include "timing/backend_timing.hpp"

namespace girtd {

class ModelSeries {
 public:
  // `model` must outlive this; this registers itself with it.
  ModelSeries(const Params& p, BackendTimingModel& model)
      : model_(model), fifo_(p.base_tick_ns * 1e-9), maps_(p), at_push_(model.stays_known_at_push()) {
    model.on_fifo_stay([this](uint64_t push, uint64_t pop) { fifo_.interval(push, pop); });  // stepped
    model.on_page_miss([this](uint32_t page) { maps_.page_missed(page); });
    if (at_push_) {
      fifo_.follow(model.recent_pops());
      model.watch_fifo([this](FifoPush before, uint64_t peak, FifoPush now) {
        return fifo_.push_leaving_bin(before, peak, now);
      });
    }
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

  FifoSeries fifo(uint64_t end) const {
    if (!at_push_) return fifo_.series(end);
    const BackendTimingModel::FifoWatchState w = model_.fifo_watch();
    return fifo_.series(end, w.last, w.peak);
  }
  const ScreenMaps& maps() const { return maps_.maps(); }

 private:
  BackendTimingModel& model_;
  FifoLevels fifo_;
  ScreenMapRecorder maps_;
  bool at_push_;  // pushes watched in the model (else each stay told by its stepped memory side, at the pop)
};

}  // namespace girtd
