#include "io/image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace girtd {

ImageError compare_images(const RgbImage& a, const RgbImage& b) {
  ImageError e;
  uint64_t sum = 0, sum_sq = 0;
  const size_t n = a.rgb.size() / 3;
  for (size_t i = 0; i < n; ++i) {
    bool diff = false;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(a.rgb[3 * i + c]) - int(b.rgb[3 * i + c]));
      sum += d;
      sum_sq += uint64_t(d) * d;
      e.max_abs = std::max(e.max_abs, d);
      diff = diff || d != 0;
    }
    e.differing += diff;
  }
  e.mean_abs = double(sum) / double(3 * n);
  e.rmse = std::sqrt(double(sum_sq) / double(3 * n));
  if (e.rmse > 0) e.psnr_db = 20 * std::log10(255.0 / e.rmse);
  e.differing_fraction = double(e.differing) / double(n);
  return e;
}

DepthError compare_depth(const std::vector<uint16_t>& a, const std::vector<uint16_t>& b, uint16_t clear) {
  DepthError e;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    const bool in_a = a[i] != clear, in_b = b[i] != clear;
    e.covered_a += in_a;
    e.covered_b += in_b;
    e.coverage_diff += in_a != in_b;
    if (in_a && in_b) {
      ++e.covered_both;
      e.z_max_abs = std::max(e.z_max_abs, std::abs(int(a[i]) - int(b[i])));
    }
  }
  return e;
}

}  // namespace girtd
