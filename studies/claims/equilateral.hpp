// The "200-pixel equilateral triangle" of docs/design.md §9 and the thesis'
// per-edge wasted-state formula (§4.2.9).
#pragma once

#include <functional>

#include "common/types.hpp"

namespace girtd {

// Side sqrt(800 / sqrt(3)) = 21.49 px centred (centroid) on (cx, cy), rotated
// by `angle` radians; angle 0 = apex up, pi = apex down.
Triangle equilateral_200(double cx, double cy, double angle, double z = 30000);

// The 64 sub-pixel positions of §9: an 8 x 8 grid of cell centres inside the
// pixel whose corner is (x0, y0).
void for_each_subpixel_position(double x0, double y0, const std::function<void(double cx, double cy)>& fn);

// Thesis formula: each edge whose outward normal points up wastes 2 dy
// states, each whose normal points down wastes dx + 3 dy / 2.
double thesis_wasted_states(const Triangle& t);

}  // namespace girtd
