#include "dda/steep_attributes.hpp"

#include <algorithm>
#include <cmath>

namespace girtd {
namespace {

struct Point {
  double x, y;
};

constexpr double kDError = 0.25;  // px: the D error of the longest walk (models/dda/README.md)

// Where the DDA may emit: the triangle grown by `reach` at every edge,
// clipped to the walk's box; its corners, and the start pixel (whose value
// the register starts from), from `from`.
std::vector<Point> emit_region(const TriangleSetup& s, const WalkBox& w, Point from) {
  const double reach = w.q + kDError;
  std::vector<Point> poly;
  for (int k = 0; k < 3; ++k) {  // grown edges k-1 and k meet at the grown v[k]
    const EdgeEquation &e = s.edge[(k + 2) % 3], &f = s.edge[k];
    const double det = e.a * f.b - e.b * f.a;
    if (det == 0) return {{double(w.x0) - from.x, double(w.y0) - from.y}};
    const double ce = e.c + reach, cf = f.c + reach;
    poly.push_back({(e.b * cf - f.b * ce) / det, (f.a * ce - e.a * cf) / det});
  }
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
    if (poly.empty()) break;
  }
  poly.push_back({double(w.x0), double(w.y0)});
  for (Point& p : poly) p = {p.x - from.x, p.y - from.y};
  return poly;
}

// The value range the register may reach and its largest derivative, less
// the rounding of the derivatives (half an LSB a step) over the longest walk.
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

bool fits(double at_origin, double dx, double dy, const Room& room, const std::vector<Point>& corners) {
  if (std::abs(dx) > room.d_max || std::abs(dy) > room.d_max) return false;
  for (const Point& c : corners) {
    const double at = at_origin + dx * c.x + dy * c.y;
    if (!(at >= room.lo && at <= room.hi)) return false;
  }
  return true;
}

}  // namespace

bool limit_steep_plane(SteepPlane& plane, double centroid_value, const FixFormat& fmt, const WalkBox& walk,
                       const TriangleSetup& s) {
  const Room room = room_of(fmt, walk);
  const std::array<Vertex, 3>& v = s.v;
  // From the centroid, whose value lies within the corners' (inside the room).
  const Point c{(v[0].x + v[1].x + v[2].x) / 3, (v[0].y + v[1].y + v[2].y) / 3};
  const std::vector<Point> corners = emit_region(s, walk, c);
  if (fits(centroid_value, plane.dx, plane.dy, room, corners)) return false;
  // u along the longest edge, n across it.
  double ux = 1, uy = 0, longest = -1;
  for (int i = 0; i < 3; ++i) {
    const double ex = v[(i + 1) % 3].x - v[i].x, ey = v[(i + 1) % 3].y - v[i].y, len = std::hypot(ex, ey);
    if (len > longest && len > 0) longest = len, ux = ex / len, uy = ey / len;
  }
  const double nx = -uy, ny = ux;
  double along = plane.dx * ux + plane.dy * uy, across = plane.dx * nx + plane.dy * ny;
  // The along part alone, cut until it fits (the centroid's value does).
  for (const Point& k : corners) {
    const double pa = k.x * ux + k.y * uy, at = centroid_value + along * pa;
    if (at > room.hi) along *= (room.hi - centroid_value) / (along * pa);
    else if (at < room.lo) along *= (room.lo - centroid_value) / (along * pa);
  }
  // Then each corner bounds the across part to an interval holding 0.
  double lo = -INFINITY, hi = INFINITY;
  for (const Point& k : corners) {
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
  plane = {centroid_value + dx * (walk.x0 - c.x) + dy * (walk.y0 - c.y), dx, dy};
  return true;
}

}  // namespace girtd
