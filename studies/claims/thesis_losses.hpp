// How DDApix as written (thesis appendix) fares: pixels it loses against a
// brute-force test of the same anchored lattice, and its wasted states on the
// 200-pixel equilateral triangle of §9 placed on its 128 x 96 screen.
#pragma once

#include <cstdint>

#include "config/params.hpp"
#include "thesis/ddapix.hpp"

namespace girtd {

struct ThesisLossSample {
  int triangles = 0;            // prepared (prepdda returned 1)
  int triangles_losing = 0;     // at least one inside pixel never emitted
  uint64_t inside_pixels = 0;   // lattice pixels inside (within the limits)
  uint64_t lost_pixels = 0;
  uint64_t outside_limit_emits = 0;  // pixels emitted one column past Xmin/Xmax
};

ThesisLossSample measure_thesis_losses(const Params& p, ThesisInside inside, int count, uint32_t seed);

struct ThesisEfficiency {
  double mean_emitted = 0, mean_wasted = 0, mean_formula = 0, mean_efficiency = 0;
};

// apex_up: the §9 triangle apex up, else apex down; 64 sub-pixel positions.
ThesisEfficiency measure_thesis_equilateral(const Params& p, bool apex_up);

}  // namespace girtd
