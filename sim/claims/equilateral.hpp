// The "200-pixel equilateral triangle" of GIRTD.md §9 and the thesis'
// per-edge wasted-state formula (§4.2.9).
#pragma once

#include "common/types.hpp"

namespace girtd {

// Side sqrt(800 / sqrt(3)) = 21.49 px centred (centroid) on (cx, cy), rotated
// by `angle` radians; angle 0 = apex up, pi = apex down.
Triangle equilateral_200(double cx, double cy, double angle, double z = 30000);

// Thesis formula: each edge whose outward normal points up wastes 2 dy
// states, each whose normal points down wastes dx + 3 dy / 2.
double thesis_wasted_states(const Triangle& t);

}  // namespace girtd
