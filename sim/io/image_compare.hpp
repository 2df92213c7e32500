// Two RGB frames of one size compared channel by channel (0..255): for the
// benches' error tables and their counts of changed pixels.
#pragma once

#include <cstdint>

#include "io/png_io.hpp"

namespace girtd {

struct ImageError {
  double mean_abs = 0;      // over every channel of every pixel
  int max_abs = 0;
  uint64_t differing = 0;   // pixels with any channel different
  double differing_fraction = 0;
};

ImageError compare_images(const RgbImage& a, const RgbImage& b);

}  // namespace girtd
