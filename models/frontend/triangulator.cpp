#include "frontend/triangulator.hpp"

#include <cmath>
#include <cstdlib>

namespace girtd {
namespace {

double cross3(const Point2& a, const Point2& b, const Point2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Inside or on the border of triangle abc (orientation `o` = +1 or -1).
bool in_triangle(const Point2& q, const Point2& a, const Point2& b, const Point2& c, double o) {
  return cross3(a, b, q) * o >= 0 && cross3(b, c, q) * o >= 0 && cross3(c, a, q) * o >= 0;
}

bool same_point(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }

// The turn at corner b (from a, to c) seen with orientation o: +1 convex,
// -1 concave, 0 straight (within kStraightTolerance of |e1||e2|, so that
// rounding does not make a straight corner concave).
int turn(const Point2& a, const Point2& b, const Point2& c, double o) {
  const double z = cross3(a, b, c) * o;
  const double e1 = std::hypot(b.x - a.x, b.y - a.y), e2 = std::hypot(c.x - b.x, c.y - b.y);
  if (std::fabs(z) <= kStraightTolerance * e1 * e2) return 0;
  return z > 0 ? 1 : -1;
}

void fan(int from, int n, std::vector<TriangleIndices>& out) {
  for (int k = 1; k + 1 < n; ++k) out.push_back({{from, (from + k) % n, (from + k + 1) % n}, {}});
}

// Clips ears off the polygon; false if it got stuck (self-intersection).
bool ear_clip(const std::vector<Point2>& p, double o, std::vector<TriangleIndices>& out) {
  std::vector<int> idx;
  for (int i = 0; i < static_cast<int>(p.size()); ++i) idx.push_back(i);
  auto clip_at = [&](size_t k) {
    const size_t m = idx.size();
    out.push_back({{idx[(k + m - 1) % m], idx[k], idx[(k + 1) % m]}, {}});
    idx.erase(idx.begin() + static_cast<long>(k));
  };
  while (idx.size() > 3) {
    const size_t m = idx.size();
    bool clipped = false;
    for (size_t k = 0; k < m && !clipped; ++k) {
      const Point2& a = p[idx[(k + m - 1) % m]];
      const Point2& b = p[idx[k]];
      const Point2& c = p[idx[(k + 1) % m]];
      if (turn(a, b, c, o) <= 0) continue;  // concave or straight: not an ear
      bool empty = true;
      for (size_t j = 0; j < m && empty; ++j) {
        const Point2& q = p[idx[j]];
        if (j == k || j == (k + 1) % m || j == (k + m - 1) % m) continue;
        if (same_point(q, a) || same_point(q, b) || same_point(q, c)) continue;
        empty = !in_triangle(q, a, b, c, o);
      }
      if (empty) {
        clip_at(k);
        clipped = true;
      }
    }
    // A vertex on a straight line adds no area: dropping it (a zero-area
    // triangle, which the preparer discards) keeps the rest correct.
    for (size_t k = 0; k < m && !clipped; ++k)
      if (turn(p[idx[(k + m - 1) % m]], p[idx[k]], p[idx[(k + 1) % m]], o) == 0) {
        clip_at(k);
        clipped = true;
      }
    if (!clipped) return false;
  }
  out.push_back({{idx[0], idx[1], idx[2]}, {}});
  return true;
}

}  // namespace

Triangulation triangulate(const std::vector<Point2>& p) {
  Triangulation t;
  triangulate(p, t);
  return t;
}

void triangulate(const std::vector<Point2>& p, Triangulation& t) {
  t.triangles.clear();
  t.method = TriangulationMethod::kConvexFan;
  t.concave_vertices = 0;
  const int n = static_cast<int>(p.size());
  if (n < 3) return;
  double area2 = 0;
  for (int i = 0; i < n; ++i) area2 += p[i].x * p[(i + 1) % n].y - p[(i + 1) % n].x * p[i].y;
  const double o = area2 >= 0 ? 1.0 : -1.0;
  int concave_at = -1;
  for (int i = 0; i < n; ++i)
    if (turn(p[(i + n - 1) % n], p[i], p[(i + 1) % n], o) < 0) {
      ++t.concave_vertices;
      concave_at = i;
    }
  if (t.concave_vertices == 0) {
    fan(0, n, t.triangles);
  } else if (t.concave_vertices == 1) {
    t.method = TriangulationMethod::kConcaveFan;
    fan(concave_at, n, t.triangles);
  } else {
    t.method = TriangulationMethod::kEarClipping;
    if (!ear_clip(p, o, t.triangles)) {
      t.triangles.clear();
      t.method = TriangulationMethod::kFallbackFan;
      fan(0, n, t.triangles);
    }
  }
  for (TriangleIndices& tri : t.triangles)
    for (int e = 0; e < 3; ++e) {
      const int a = tri.v[e], b = tri.v[(e + 1) % 3];
      const int d = std::abs(a - b);
      tri.made_edge[e] = !(d == 1 || d == n - 1);
    }
}

}  // namespace girtd
