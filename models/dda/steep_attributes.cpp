#include "dda/steep_attributes.hpp"

#include <algorithm>
#include <cmath>

namespace girtd {
namespace {

using Point = EmitRegion::Point;

constexpr double kDError = 0.25;  // px: the D error of the longest walk (models/dda/README.md)

// The value range the register may reach and its largest derivative, less
// the rounding of the derivatives over the longest walk: an LSB a step,
// twice the half LSB each rounded derivative can be off.
struct Room {
  double lo, hi, d_max;
};

Room room_of(const FixFormat& fmt, const WalkBox& w) {
  const double lsb = 1.0 / static_cast<double>(fmt.one());
  const double steps = (w.box.x1 - w.box.x0) + (w.box.y1 - w.y0) + 2;
  const double drift = steps * lsb;
  return {static_cast<double>(fmt.raw_min()) * lsb + drift, static_cast<double>(fmt.raw_max()) * lsb - drift,
          static_cast<double>(fmt.raw_max()) * lsb};
}

// The plane, `at_origin` where `corners` are measured from, within the room at every corner.
template <class Corners>
bool fits(double at_origin, double dx, double dy, const Room& room, const Corners& corners) {
  if (std::abs(dx) > room.d_max || std::abs(dy) > room.d_max) return false;
  for (const Point& c : corners) {
    const double at = at_origin + dx * c.x + dy * c.y;
    if (!(at >= room.lo && at <= room.hi)) return false;
  }
  return true;
}

}  // namespace

bool fits_walk_box(const SteepPlane& plane, const FixFormat& fmt, const WalkBox& walk) {
  const double l = walk.box.x0 - walk.x0, r = walk.box.x1 - walk.x0, bottom = walk.box.y1 - walk.y0;
  const Point corners[4] = {{l, 0}, {r, 0}, {l, bottom}, {r, bottom}};
  return fits(plane.v, plane.dx, plane.dy, room_of(fmt, walk), corners);
}

EmitRegion emit_region(const TriangleSetup& s, const WalkBox& w) {
  EmitRegion r;
  const std::array<Vertex, 3>& v = s.v;
  r.centroid = {(v[0].x + v[1].x + v[2].x) / 3, (v[0].y + v[1].y + v[2].y) / 3};
  double longest = 0;
  for (int i = 0; i < 3; ++i) {
    const double ex = v[(i + 1) % 3].x - v[i].x, ey = v[(i + 1) % 3].y - v[i].y, len = std::hypot(ex, ey);
    if (len > longest) longest = len, r.ux = ex / len, r.uy = ey / len;
  }
  // The triangle grown by `reach` at every edge: grown edges k-1 and k meet at the grown v[k].
  const double reach = w.q + kDError;
  std::vector<Point> poly;
  for (int k = 0; k < 3; ++k) {
    const EdgeEquation &e = s.edge[(k + 2) % 3], &f = s.edge[k];
    const double det = e.a * f.b - e.b * f.a;
    if (det == 0) break;
    const double ce = e.c + reach, cf = f.c + reach;
    poly.push_back({(e.b * cf - f.b * ce) / det, (f.a * ce - e.a * cf) / det});
  }
  if (poly.size() < 3) poly.clear();
  // Sutherland-Hodgman against the box's four sides: keep (x, y) with sx * x + sy * y <= lim.
  const double sides[4][3] = {{-1, 0, -double(w.box.x0)}, {1, 0, double(w.box.x1)}, {0, -1, -double(w.y0)},
                              {0, 1, double(w.box.y1)}};
  for (const auto& side : sides) {
    std::vector<Point> kept;
    for (size_t i = 0; i < poly.size(); ++i) {
      const Point p = poly[i], n = poly[(i + 1) % poly.size()];
      const double dp = side[0] * p.x + side[1] * p.y - side[2], dn = side[0] * n.x + side[1] * n.y - side[2];
      if (dp <= 0) kept.push_back(p);
      if ((dp < 0) != (dn < 0) && dp != dn) {
        const double t = dp / (dp - dn);
        kept.push_back({p.x + t * (n.x - p.x), p.y + t * (n.y - p.y)});
      }
    }
    poly = std::move(kept);
  }
  poly.push_back({double(w.x0), double(w.y0)});  // the register starts from the start pixel's value
  for (Point& p : poly) p = {p.x - r.centroid.x, p.y - r.centroid.y};
  r.corners = std::move(poly);
  return r;
}

bool limit_steep_plane(SteepPlane& plane, double centroid_value, const FixFormat& fmt, const WalkBox& walk,
                       const EmitRegion& region) {
  const Room room = room_of(fmt, walk);
  if (!(centroid_value >= room.lo && centroid_value <= room.hi)) return false;  // no cut can make it fit
  if (fits(centroid_value, plane.dx, plane.dy, room, region.corners)) return false;
  const double ux = region.ux, uy = region.uy, nx = -uy, ny = ux;
  double along = plane.dx * ux + plane.dy * uy, across = plane.dx * nx + plane.dy * ny;
  // The along part alone, cut until it fits (the centroid's value does).
  for (const Point& k : region.corners) {
    const double step = along * (k.x * ux + k.y * uy), at = centroid_value + step;
    if (at > room.hi) along *= (room.hi - centroid_value) / step;  // step > 0 here
    else if (at < room.lo) along *= (room.lo - centroid_value) / step;  // step < 0 here
  }
  // Then each corner bounds the across part to an interval holding 0.
  double lo = -INFINITY, hi = INFINITY;
  for (const Point& k : region.corners) {
    const double pn = k.x * nx + k.y * ny;
    if (pn == 0) continue;
    const double base = centroid_value + along * (k.x * ux + k.y * uy);
    const double a = (room.lo - base) / pn, b = (room.hi - base) / pn;
    lo = std::max(lo, std::min(a, b));
    hi = std::min(hi, std::max(a, b));
  }
  across = std::clamp(across, std::min(lo, 0.0), std::max(hi, 0.0));
  double dx = along * ux + across * nx, dy = along * uy + across * ny;
  const double steepest = std::max(std::abs(dx), std::abs(dy));
  if (steepest > room.d_max) dx *= room.d_max / steepest, dy *= room.d_max / steepest;
  const double v = centroid_value + dx * (walk.x0 - region.centroid.x) + dy * (walk.y0 - region.centroid.y);
  if (!std::isfinite(v) || !std::isfinite(dx) || !std::isfinite(dy)) return false;
  plane = {v, dx, dy};
  return true;
}

}  // namespace girtd
