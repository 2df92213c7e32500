// Two frames of one size compared: colour channel by channel (0..255) and,
// where both Z planes are known, coverage (a pixel whose Z is not the clear
// value was drawn) and depth. One comparison for the benches' and the
// accuracy command's error tables.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "io/png_io.hpp"

namespace girtd {

struct ImageError {
  double mean_abs = 0;      // over every channel of every pixel
  int max_abs = 0;
  double rmse = 0;          // over every channel of every pixel
  std::optional<double> psnr_db;  // 20 log10(255 / rmse); none when the frames are equal
  uint64_t differing = 0;   // pixels with any channel different
  double differing_fraction = 0;
};

ImageError compare_images(const RgbImage& a, const RgbImage& b);

struct DepthError {
  uint64_t covered_a = 0, covered_b = 0;
  uint64_t coverage_diff = 0;  // pixels drawn in one frame and not the other
  uint64_t covered_both = 0;
  int z_max_abs = 0;           // over the pixels both drew
};

DepthError compare_depth(const std::vector<uint16_t>& a, const std::vector<uint16_t>& b, uint16_t clear);

}  // namespace girtd
