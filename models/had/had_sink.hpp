// The HAD as the golden DDA's pixel sink: pixel by pixel (DdaEmit), or a
// span's pixels as one run (dda/dda_run.hpp), counting the pixels it gets.
#pragma once

#include <cstdint>

#include "dda/dda_engine.hpp"
#include "had/had.hpp"

namespace girtd {

struct HadSink {
  static constexpr bool kTakesRuns = true;
  Had& had;
  uint64_t& pixels;  // pixels generated
  int layer;         // the triangle's seam_layer() (-1: not known)

  void operator()(const DdaEmit& e) const {
    ++pixels;
    had.update(e.pixel, layer, e.covered);
  }
  template <typename Run>
  [[gnu::always_inline]] void run(const Run& run_pixels) const {
    pixels += static_cast<uint64_t>(run_pixels.size());
    had.update_run(run_pixels, layer);
  }
};

}  // namespace girtd
