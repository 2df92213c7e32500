#include "io/image_compare.hpp"

#include <algorithm>
#include <cstdlib>

namespace girtd {

ImageError compare_images(const RgbImage& a, const RgbImage& b) {
  ImageError e;
  uint64_t sum = 0;
  const size_t n = a.rgb.size() / 3;
  for (size_t i = 0; i < n; ++i) {
    bool diff = false;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(a.rgb[3 * i + c]) - int(b.rgb[3 * i + c]));
      sum += d;
      e.max_abs = std::max(e.max_abs, d);
      diff = diff || d != 0;
    }
    e.differing += diff;
  }
  e.mean_abs = double(sum) / double(3 * n);
  e.differing_fraction = double(e.differing) / double(n);
  return e;
}

}  // namespace girtd
