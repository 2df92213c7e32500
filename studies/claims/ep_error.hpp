// Fixed-point error of the DDA's EPs against the exact planes (§4.2.8).
#pragma once

#include <cstdint>

#include "config/params.hpp"

namespace girtd {

struct EpErrorSample {
  double max_color_lsb = 0;   // |R, G, B EP value - exact| in colour LSBs
  double max_d_px = 0;        // |D EP value - exact distance| in pixels
  double max_z_lsb = 0;
  double max_t_lsb = 0;       // T on its 0..256 scale
  int max_steps = 0;          // largest |X - X0| + |Y - Y0| among the pixels
  uint64_t pixels = 0;
};

// Random triangles spanning up to `span` pixels, traversed by the golden DDA;
// only pixels at most `max_steps` unit moves from the start count.
EpErrorSample measure_ep_error(const Params& p, int triangles, double span, int max_steps, uint32_t seed);

}  // namespace girtd
