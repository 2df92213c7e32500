#include "common/triangle_setup.hpp"

#include <algorithm>
#include <cmath>

namespace girtd {
namespace {

double attr_of(const Vertex& v, int a) {
  switch (a) {
    case kR: return v.r;
    case kG: return v.g;
    case kB: return v.b;
    case kT: return v.t;
    default: return v.z;
  }
}

}  // namespace

std::optional<TriangleSetup> setup_triangle(const Triangle& t) {
  TriangleSetup s;
  s.v = t.v;
  auto pv_of = [](const std::array<Vertex, 3>& v) {
    return (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
  };
  double pv = pv_of(s.v);
  if (pv == 0 || !std::isfinite(pv)) return std::nullopt;
  for (int i = 0; i < 3; ++i) s.interior[i] = (t.interior_edges >> i) & 1;
  if (pv > 0) {  // clockwise on screen: reorder (§3 winding normalization)
    std::swap(s.v[1], s.v[2]);
    pv = -pv;
    s.reordered = true;
    // The edges now run v0 -> v2 -> v1 -> v0: the written edges 2, 1, 0.
    s.interior = {s.interior[2], s.interior[1], s.interior[0]};
  }
  for (int i = 0; i < 3; ++i) {
    const Vertex& p = s.v[i];
    const Vertex& q = s.v[(i + 1) % 3];
    const double a = q.y - p.y, b = p.x - q.x;
    const double len = std::sqrt(a * a + b * b);
    if (len == 0) return std::nullopt;
    s.edge[i] = {a / len, b / len, (-a * p.x - b * p.y) / len};
  }
  const Vertex& v1 = s.v[0];
  const Vertex& v2 = s.v[1];
  const Vertex& v3 = s.v[2];
  for (int a = 0; a < kAttrCount; ++a) {
    const double p21 = attr_of(v2, a) - attr_of(v1, a);
    const double p31 = attr_of(v3, a) - attr_of(v1, a);
    AttributePlane& pl = s.attr[a];
    pl.x0 = v1.x;
    pl.y0 = v1.y;
    pl.p0 = attr_of(v1, a);
    pl.dx = (p21 * (v3.y - v1.y) - p31 * (v2.y - v1.y)) / pv;
    pl.dy = (p31 * (v2.x - v1.x) - p21 * (v3.x - v1.x)) / pv;
  }
  s.min_x = std::min({v1.x, v2.x, v3.x});
  s.max_x = std::max({v1.x, v2.x, v3.x});
  s.min_y = std::min({v1.y, v2.y, v3.y});
  s.max_y = std::max({v1.y, v2.y, v3.y});
  return s;
}

PixelBox fringe_box(const TriangleSetup& s, double q, const Window& w) {
  auto lo = [](double v) { return static_cast<int>(std::max(-1e9, std::ceil(v))); };
  auto hi = [](double v) { return static_cast<int>(std::min(1e9, std::floor(v))); };
  PixelBox b;
  b.x0 = std::max(lo(s.min_x - q), w.x0);
  b.x1 = std::min(hi(s.max_x + q), w.x1);
  b.y0 = std::max(lo(s.min_y - q), w.y0);
  b.y1 = std::min(hi(s.max_y + q), w.y1);
  return b;
}

std::optional<StartPoint> select_start_point(const TriangleSetup& s, const Window& w) {
  auto inside_triangle = [&](double x, double y) {
    for (const EdgeEquation& e : s.edge)
      if (e.at(x, y) < 0) return false;
    return true;
  };
  const double wx0 = w.x0, wy0 = w.y0, wx1 = w.x1, wy1 = w.y1;
  if (inside_triangle(wx0, wy0)) return StartPoint{wx0, wy0};

  std::optional<StartPoint> best;
  auto consider = [&](double x, double y) {
    if (!(x >= wx0 && x <= wx1 && y >= wy0 && y <= wy1)) return;
    if (!best || y < best->y || (y == best->y && x < best->x)) best = StartPoint{x, y};
  };
  for (const Vertex& v : s.v) consider(v.x, v.y);
  for (int i = 0; i < 3; ++i) {
    const Vertex& p = s.v[i];
    const Vertex& q = s.v[(i + 1) % 3];
    // Crossings with the horizontal borders y = wy0, wy1.
    for (double yb : {wy0, wy1}) {
      if (p.y == q.y) continue;
      const double u = (yb - p.y) / (q.y - p.y);
      if (u >= 0 && u <= 1) consider(p.x + u * (q.x - p.x), yb);
    }
    // Crossings with the vertical borders x = wx0, wx1.
    for (double xb : {wx0, wx1}) {
      if (p.x == q.x) continue;
      const double u = (xb - p.x) / (q.x - p.x);
      if (u >= 0 && u <= 1) consider(xb, p.y + u * (q.y - p.y));
    }
  }
  // A window lying wholly inside the triangle has its corner inside (tested
  // above), so no candidate means no overlap.
  return best;
}

SharedEdge shared_edge(const TriangleSetup& s, int i, const Window& w) {
  const Vertex& u = s.v[i];
  const Vertex& v = s.v[(i + 1) % 3];
  const bool forward = u.y < v.y || (u.y == v.y && u.x < v.x);
  SharedEdge e;
  e.p = forward ? u : v;
  const Vertex& q = forward ? v : u;
  e.sign = forward ? 1 : -1;
  e.nx = q.y - e.p.y;
  e.ny = e.p.x - q.x;
  e.len = std::sqrt(e.nx * e.nx + e.ny * e.ny);
  e.a = e.nx / e.len;
  e.b = e.ny / e.len;
  // The window's middle projected onto the edge's line: the fixed-point
  // walk's error grows with the distance from here (so it stays within the
  // window's half diagonal), and both sides pick the same point.
  const double cx = 0.5 * (w.x0 + w.x1) - e.p.x, cy = 0.5 * (w.y0 + w.y1) - e.p.y;
  const double dx = q.x - e.p.x, dy = q.y - e.p.y;
  const double t = (cx * dx + cy * dy) / (dx * dx + dy * dy);
  e.ref_x = static_cast<int>(std::clamp(std::round(e.p.x + t * dx), -2e9, 2e9));
  e.ref_y = static_cast<int>(std::clamp(std::round(e.p.y + t * dy), -2e9, 2e9));
  return e;
}

double norm_q(double d, double q) {
  if (d >= 0) return 1.0;
  if (q <= 0 || d <= -q) return 0.0;
  return 1.0 + d / q;
}

bool is_hardware_q(double q) {
  if (q == 0) return true;
  for (int k = -4; k <= 3; ++k)
    if (q == std::ldexp(1.0, k)) return true;
  return false;
}

int q_log2(double q) {
  int e = 0;
  std::frexp(q, &e);
  return e - 1;
}

}  // namespace girtd
