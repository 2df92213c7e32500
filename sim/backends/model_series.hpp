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
    if (at_push_) fifo_.follow(model.recent_pops());
  }
  ModelSeries(const ModelSeries&) = delete;
  ModelSeries& operator=(const ModelSeries&) = delete;

  void begin_frame() { maps_.begin_frame(); }
  // After model.pixel() for the pixel at (x, y).
  void pixel(int x, int y) {
    if (at_push_) {
      const FifoPush s = model_.last_push();
      fifo_.pushed(s.tick, s.count_after);
    }
    maps_.drawn(x, y);
  }
  void end_triangle(uint64_t dda_cycles, uint64_t emitted) { maps_.end_triangle(dda_cycles, emitted); }

  FifoSeries fifo(uint64_t end) const { return fifo_.series(end); }
  const ScreenMaps& maps() const { return maps_.maps(); }

 private:
  BackendTimingModel& model_;
  FifoLevels fifo_;
  ScreenMapRecorder maps_;
  bool at_push_;  // each push told here (else by the model's stepped memory side, at the pop)
};

}  // namespace girtd
