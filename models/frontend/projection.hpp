// §3 perspective projection and the map to pixels.
//   Xp = Xs/Zs * D/S, Yp = Ys/Zs * D/S          (-1..1 across the plane)
//   x = (W - 1)/2 * (1 + Xp), y = (H - 1)/2 * (1 - Yp)
// The pixel map is the thesis' own program's (x = KC(1 + xp), KC = 63.5 for
// 128 pixels, y flipped) scaled to the screen: -1 and +1 land on the centres
// of the first and last pixel columns, which the lattice samples.
//   Zp = Zmax/(Zmax - Zmin) (1 - Zmin/Zs) P,    P = depth.max_mapped (65534)
// Zp is affine in 1/Zs, as x and y are, so the DDA's linear interpolation of
// Z across the screen is exact.
#pragma once

#include "frontend/vec3.hpp"

namespace girtd {

// A camera-space point (Zs > 0) on the projection plane: -1..1 across it.
struct PlanePoint {
  double xp = 0, yp = 0;
};

// Xp = Xs/Zs * D/S, Yp = Ys/Zs * D/S.
inline PlanePoint project(const Vec3& s, double d_over_s) { return {s.x / s.z * d_over_s, s.y / s.z * d_over_s}; }

struct ScreenMap {
  int width = 1024, height = 1024;
  double x(double xp) const { return 0.5 * (width - 1) * (1.0 + xp); }
  double y(double yp) const { return 0.5 * (height - 1) * (1.0 - yp); }
};

class DepthMap {
 public:
  // zmin, zmax: the frame's depth extremes (models/frontend/README.md: which
  // vertices count). zmax == zmin maps every depth to 0.
  DepthMap(double zmin, double zmax, double p) : zmin_(zmin), zmax_(zmax), p_(p) {}
  // Clamped to 0..P against rounding at the ends.
  double zp(double zs) const;

 private:
  double zmin_, zmax_, p_;
};

}  // namespace girtd
