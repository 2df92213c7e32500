// preparer.steep_attributes limited: an attribute plane so steep that its
// EP register would leave its format at a pixel the DDA may emit (a needle
// triangle: a tiny extent across, a huge derivative; its fringe reaches
// where the plane is far out of range) gets its derivative across the
// triangle's longest edge cut until every value there fits, with a margin
// for the rounding the walk adds up. Where the DDA may emit: every edge's
// distance at least -(Q + 0.25 px, the D error of the longest walk), within
// the pixel box, and the start pixel.
// The value at the triangle's centroid (within its corners' values) stays
// as computed, and so does the derivative along the longest edge unless it
// alone leaves the format (then it is cut too); the start value follows.
// Inside a needle (under a pixel across) the picture moves by at most the
// triangle's own colour or depth spread across it. A plane whose centroid
// value does not fit the format (a format too narrow for the attribute's
// range) is left as computed: its clamps and wraps are counted as ever.
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

// What every plane of one triangle is tested against, found once.
struct EmitRegion {
  struct Point {
    double x, y;
  };
  std::vector<Point> corners;  // of where the DDA may emit, and the start pixel; from the centroid
  Point centroid;
  double ux = 1, uy = 0;       // along the longest edge
};

EmitRegion emit_region(const TriangleSetup& s, const WalkBox& walk);

// True when `plane` fits `fmt` over the whole pixel box: over the emit
// region too (it lies in the box), so no region need be found. The test
// most planes pass, and the simulator's, not the modeled preparer's.
bool fits_walk_box(const SteepPlane& plane, const FixFormat& fmt, const WalkBox& walk);

// `plane` (at the start pixel; `centroid_value`: the plane at the region's
// centroid) limited for `fmt`; returns false and leaves it when it already
// fits, or cannot be made to.
bool limit_steep_plane(SteepPlane& plane, double centroid_value, const FixFormat& fmt, const WalkBox& walk,
                       const EmitRegion& region);

}  // namespace girtd
