// Measures the DDA's states on the 200-pixel equilateral triangle (§9):
// 64 sub-pixel positions on an 8 x 8 grid, apex up, apex down, and random
// rotations.
#pragma once

#include <string>

#include "config/params.hpp"

namespace girtd {

struct EfficiencySample {
  double mean_emitted = 0, mean_wasted = 0, min_wasted = 0, max_wasted = 0;
  double mean_efficiency = 0, min_efficiency = 0, max_efficiency = 0;
  double mean_thesis_wasted = 0;  // the per-edge formula on the same triangles
  int triangles = 0;
};

enum class Orientation { kApexUp, kApexDown, kRandom };

// `pipelined` selects the +2 clocks per line (TTL) option; q the AA width.
EfficiencySample measure_equilateral(const Params& base, Orientation o, double q, bool pipelined);

const char* orientation_name(Orientation o);

}  // namespace girtd
