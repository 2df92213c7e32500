// Where the EP formats stop drawing right (issue: stiff and extreme inputs),
// measured on the golden model for `girtd claims`: the largest overhang a
// screen-filling triangle may have, and what the preparer does as a
// triangle's area goes to zero (its derivatives grow without bound).
#pragma once

#include <cstdint>

#include "config/params.hpp"

namespace girtd {

// A screen-filling right triangle with its corners `overhang` px beyond
// the screen: all 1,048,576 pixels, no wrap, no clamp?
bool overhang_drawn_right(const Params& p, double overhang);
// Its corners reach the trace format's limit of 1e6 px here.
inline constexpr double kLargestOverhang = (1e6 - 2046) / 2;
// The largest whole overhang drawn right, by bisection up to kLargestOverhang.
double largest_safe_overhang(const Params& p);

struct CollapseSample {
  int triangles = 0, dropped = 0;  // dropped: no area, or no lattice point
  uint64_t clamped_values = 0;     // start values and derivatives clamped
  uint64_t pixels = 0;             // emitted
  int max_colour_error = 0;        // |8-bit output - reference (floor of the clamped plane)|
};

// 20 slivers 200 px long of area `area` px^2, red 0 along the base and 255 at
// the apex, so d/dy = 255 / height: clamps and their effect on the picture.
CollapseSample measure_collapse(const Params& p, double area);

}  // namespace girtd
