// The §3 triangulator: convex fan, fan from one concave vertex, ear clipping
// for several; every result covers exactly the polygon (areas sum, no
// overlaps) and marks the diagonals it made.
#include <catch2/catch.hpp>

#include <cmath>

#include "frontend/triangulator.hpp"

using namespace girtd;

namespace {

double signed_area(const std::vector<Point2>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) a += p[i].x * p[(i + 1) % p.size()].y - p[(i + 1) % p.size()].x * p[i].y;
  return a / 2;
}

double tri_area(const std::vector<Point2>& p, const TriangleIndices& t) {
  return signed_area({p[static_cast<size_t>(t.v[0])], p[static_cast<size_t>(t.v[1])], p[static_cast<size_t>(t.v[2])]});
}

// Every triangle wound like the polygon, areas summing to the polygon's, and
// no point of a dense grid inside two triangles (no overlap).
void check_exact_cover(const std::vector<Point2>& p, const Triangulation& t) {
  REQUIRE(t.triangles.size() == p.size() - 2);
  double sum = 0;
  for (const TriangleIndices& tri : t.triangles) {
    const double a = tri_area(p, tri);
    CHECK(a >= 0);  // same orientation as the (counter-clockwise) polygon
    sum += a;
  }
  CHECK(sum == Approx(signed_area(p)));
  double lo_x = 1e9, hi_x = -1e9, lo_y = 1e9, hi_y = -1e9;
  for (const Point2& q : p) lo_x = std::min(lo_x, q.x), hi_x = std::max(hi_x, q.x), lo_y = std::min(lo_y, q.y), hi_y = std::max(hi_y, q.y);
  auto strictly_inside = [&](const TriangleIndices& tri, double x, double y) {
    for (int e = 0; e < 3; ++e) {
      const Point2& a = p[static_cast<size_t>(tri.v[e])];
      const Point2& b = p[static_cast<size_t>(tri.v[(e + 1) % 3])];
      if ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x) <= 0) return false;
    }
    return true;
  };
  int overlaps = 0;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 60; ++j) {
      const double x = lo_x + (hi_x - lo_x) * (i + 0.37) / 61, y = lo_y + (hi_y - lo_y) * (j + 0.61) / 61;
      int n = 0;
      for (const TriangleIndices& tri : t.triangles) n += strictly_inside(tri, x, y);
      overlaps += n > 1;
    }
  CHECK(overlaps == 0);
}

int made_edges(const Triangulation& t) {
  int n = 0;
  for (const TriangleIndices& tri : t.triangles) n += tri.made_edge[0] + tri.made_edge[1] + tri.made_edge[2];
  return n;
}

}  // namespace

TEST_CASE("triangulator: convex hexagon is fanned from vertex 0", "[frontend]") {
  std::vector<Point2> p;
  for (int k = 0; k < 6; ++k) p.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3)});
  const Triangulation t = triangulate(p);
  CHECK(t.method == TriangulationMethod::kConvexFan);
  CHECK(t.concave_vertices == 0);
  CHECK(t.triangles[0].v == std::array<int, 3>{0, 1, 2});
  check_exact_cover(p, t);
  // n - 3 = 3 diagonals, each shared by two triangles: 6 marked edges.
  CHECK(made_edges(t) == 6);
}

TEST_CASE("triangulator: one concave vertex (L shape) fans from it", "[frontend]") {
  // L: area 2x1 + 1x1 = 3; concave vertex 3 at (1, 1).
  const std::vector<Point2> p = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const Triangulation t = triangulate(p);
  CHECK(t.method == TriangulationMethod::kConcaveFan);
  CHECK(t.concave_vertices == 1);
  for (const TriangleIndices& tri : t.triangles) CHECK(tri.v[0] == 3);
  CHECK(signed_area(p) == Approx(3));
  check_exact_cover(p, t);
  // A fan from the same vertex in a clockwise polygon works too.
  std::vector<Point2> cw(p.rbegin(), p.rend());
  const Triangulation tc = triangulate(cw);
  CHECK(tc.concave_vertices == 1);
  double sum = 0;
  for (const TriangleIndices& tri : tc.triangles) sum += tri_area(cw, tri);
  CHECK(sum == Approx(-3));
}

TEST_CASE("triangulator: two concave vertices (U shape) need ear clipping", "[frontend]") {
  // U: 3x3 square minus the 1x2 notch from the top middle: area 9 - 2 = 7.
  const std::vector<Point2> p = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  const Triangulation t = triangulate(p);
  CHECK(t.concave_vertices == 2);
  CHECK(t.method == TriangulationMethod::kEarClipping);
  CHECK(signed_area(p) == Approx(7));
  check_exact_cover(p, t);
  // A fan from vertex 0 would be wrong here: triangle (0, 3, 4) pokes into the notch.
}

TEST_CASE("triangulator: five concave vertices (star)", "[frontend]") {
  std::vector<Point2> p;
  for (int k = 0; k < 10; ++k) {
    const double a = M_PI / 2 + M_PI * k / 5, r = k % 2 ? 0.4 : 1.0;
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  const Triangulation t = triangulate(p);
  CHECK(t.concave_vertices == 5);
  CHECK(t.method == TriangulationMethod::kEarClipping);
  // Area: 10 triangles (centre, outer k, inner k+1), each 1/2 x 1 x 0.4 x sin 36 deg.
  CHECK(signed_area(p) == Approx(10 * 0.5 * 0.4 * std::sin(M_PI / 5)));
  check_exact_cover(p, t);
}

TEST_CASE("triangulator: a collinear vertex and a self-intersecting bow-tie", "[frontend]") {
  // Square with an extra vertex in the middle of its bottom edge: still convex.
  const std::vector<Point2> p = {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}};
  const Triangulation t = triangulate(p);
  CHECK(t.concave_vertices == 0);
  CHECK(t.triangles.size() == 3);
  // Bow-tie: not a simple polygon; it still gets n - 2 triangles.
  const Triangulation b = triangulate({{0, 0}, {2, 2}, {2, 0}, {0, 2}});
  CHECK(b.triangles.size() == 2);
}

TEST_CASE("triangulator: a corner straight but for rounding is not concave", "[frontend]") {
  // b = a + 0.1 (c - a), on the line a-c, but in doubles cross(a, b, c) = -5.6e-17:
  // the exact test called b concave and fanned from it.
  const Point2 a{0.1, 0.3}, b{0.25, 0.41000000000000003}, c{1.6, 1.4};
  REQUIRE((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) < 0);
  const std::vector<Point2> p = {a, b, c, {0.8, 2.4}, {-0.4, 1.2}};
  const Triangulation t = triangulate(p);
  CHECK(t.concave_vertices == 0);
  CHECK(t.method == TriangulationMethod::kConvexFan);
  REQUIRE(t.triangles.size() == 3);
  double sum = 0;
  for (const TriangleIndices& tri : t.triangles) sum += tri_area(p, tri);
  CHECK(sum == Approx(signed_area(p)));
  // Bent in by 1e-6 of its edges (far above kStraightTolerance): concave after all.
  const Point2 bent{0.25 - 1e-6 * 1.1, 0.41 + 1e-6 * 1.5};
  const Triangulation u = triangulate({a, bent, c, {0.8, 2.4}, {-0.4, 1.2}});
  CHECK(u.concave_vertices == 1);
  CHECK(u.method == TriangulationMethod::kConcaveFan);
}
