// preparer.steep_attributes limited: an attribute plane so steep that its
// EP register would leave its format at a pixel the DDA may emit (a needle
// triangle: a tiny extent across, a huge derivative; its fringe reaches
// where the plane is far out of range) gets its derivative across the
// triangle's longest edge cut until every value there fits, with a margin
// for the rounding the walk adds up. Where the DDA may emit: every edge's
// distance at least -(Q + 0.25 px, the D error of the longest walk), within
// the pixel box.
// The value at the triangle's centroid (within its corners' values) and the
// derivative along the longest edge stay as computed; the start value
// follows. Inside a needle (under a pixel across) the picture moves by at
// most the triangle's own colour or depth spread across it.
// Plain arithmetic in the preparer; the DDA and the RTL are unchanged.
#pragma once

#include <vector>

#include "common/fixed_point.hpp"
#include "common/triangle_setup.hpp"

namespace girtd {

// An attribute in the preparer's terms: its value at the start pixel and
// its derivatives per pixel in x and y.
struct SteepPlane {
  double v, dx, dy;
};

// The DDA's walk: from (x0, y0), rows `y0`..`box.y1`, columns
// `box.x0`..`box.x1`, emitting where every edge's D > -q.
struct WalkBox {
  int x0, y0;
  PixelBox box;
  double q;
};

// `plane` (at the start pixel; `centroid_value`: the plane at the centroid
// of the triangle `s`) limited for `fmt` over `walk`; returns false and
// leaves it when it already fits.
bool limit_steep_plane(SteepPlane& plane, double centroid_value, const FixFormat& fmt, const WalkBox& walk,
                       const TriangleSetup& s);

}  // namespace girtd
