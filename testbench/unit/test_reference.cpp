// Unit tests for the floating-point reference rasterizer
// (models/reference/reference_rasterizer.hpp) against pixel sets and values
// worked out by hand. Pixel (x, y) is the lattice point (x, y); with Q = 0 a
// pixel is drawn iff every edge distance D_i >= 0, with Q > 0 iff every
// D_i > -Q, and nf = T * prod(Norm_Q(D_i)), Norm_Q(d) = 1 + d/Q for -Q < d < 0.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "common/triangle_setup.hpp"
#include "common/types.hpp"
#include "reference/reference_rasterizer.hpp"

namespace girtd {
namespace {

using PixelSet = std::set<std::pair<int, int>>;

Vertex vtx(double x, double y, double r = 100, double g = 100, double b = 100, double z = 1000, double t = 1) {
  Vertex v;
  v.x = x;
  v.y = y;
  v.z = z;
  v.r = r;
  v.g = g;
  v.b = b;
  v.t = t;
  return v;
}

Triangle tri(const Vertex& a, const Vertex& b, const Vertex& c) {
  Triangle t;
  t.v = {a, b, c};
  return t;
}

Triangle tri_xy(double x0, double y0, double x1, double y1, double x2, double y2) {
  return tri(vtx(x0, y0), vtx(x1, y1), vtx(x2, y2));
}

FrameSettings settings(double q, Window w = Window{0, 0, 1023, 1023}) {
  FrameSettings f;
  f.window = w;
  f.q = q;
  return f;
}

struct Run {
  bool drawn = false;
  std::vector<ReferenceSample> samples;
  PixelSet pixels() const {
    PixelSet s;
    for (const ReferenceSample& r : samples) s.insert({r.x, r.y});
    return s;
  }
  const ReferenceSample* at(int x, int y) const {
    for (const ReferenceSample& r : samples)
      if (r.x == x && r.y == y) return &r;
    return nullptr;
  }
};

Run run(const Triangle& t, const FrameSettings& f) {
  Run r;
  r.drawn = rasterize_reference(t, f, EdgeRules{}, [&](const ReferenceSample& s) { r.samples.push_back(s); });
  return r;
}

// All lattice points with x >= x0, y >= y0 and (x - x0) + (y - y0) <= n.
PixelSet right_triangle_points(int x0, int y0, int n) {
  PixelSet s;
  for (int y = y0; y <= y0 + n; ++y)
    for (int x = x0; x + y <= x0 + y0 + n; ++x) s.insert({x, y});
  return s;
}

}  // namespace

TEST_CASE("reference Q=0 right triangle on integer vertices covers x,y>=0, x+y<=8", "[reference]") {
  // (0,0),(8,0),(0,8): inside iff x >= 0, y >= 0, x + y <= 8 (edges included).
  // Count: rows y = 0..8 have 9 - y pixels: 9+8+...+1 = 45.
  const Run r = run(tri_xy(0, 0, 8, 0, 0, 8), settings(0));
  CHECK(r.drawn);
  CHECK(r.samples.size() == 45);
  CHECK(r.pixels() == right_triangle_points(0, 0, 8));
  // Each pixel once.
  CHECK(r.pixels().size() == r.samples.size());
  // With Q = 0 every drawn pixel is fully covered: nf = T = 1.
  for (const ReferenceSample& s : r.samples) CHECK(s.nf == 1.0);
}

TEST_CASE("reference Q=1 right triangle adds the fringe x+y=9 and nf there is 1-1/sqrt2", "[reference]") {
  // Q = 1: D_i > -1. Legs: x > -1 and y > -1 -> x, y >= 0 (the window clips
  // -1 anyway). Hypotenuse: D = -(x+y-8)/sqrt2 > -1 -> x+y < 8+sqrt2 = 9.41:
  // x+y = 9 (D = -0.7071) in, x+y = 10 (D = -1.414) out.
  // Count x, y >= 0, x + y <= 9: 10+9+...+1 = 55.
  const Run r = run(tri_xy(0, 0, 8, 0, 0, 8), settings(1));
  CHECK(r.drawn);
  CHECK(r.samples.size() == 55);
  CHECK(r.pixels() == right_triangle_points(0, 0, 9));
  // Fringe pixel (5, 4): D_hyp = -(5+4-8)/sqrt2 = -0.70711; legs D = 5, 4.
  // Norm = 1 - 0.70711 = 0.29289; T = 1 -> nf = 0.29289.
  const ReferenceSample* s = r.at(5, 4);
  REQUIRE(s != nullptr);
  std::array<double, 3> d = s->d;
  std::sort(d.begin(), d.end());
  CHECK(d[0] == Approx(-0.7071067811865476));
  CHECK(d[1] == Approx(4.0));
  CHECK(d[2] == Approx(5.0));
  CHECK(s->nf == Approx(0.2928932188134524));
  // 0.29289 * 256 = 74.98 -> truncated to 74.
  CHECK(quantize_reference(*s).nf == 74);
  // Pixels on the edges have D = 0 -> Norm = 1: (4, 4) on the hypotenuse, (0, 3) on a leg.
  REQUIRE(r.at(4, 4) != nullptr);
  CHECK(r.at(4, 4)->nf == Approx(1.0));
  CHECK(quantize_reference(*r.at(4, 4)).nf == 256);
  CHECK(r.at(0, 3)->nf == Approx(1.0));
}

TEST_CASE("reference Q=1 fringe is strict at D = -Q when the window does not clip", "[reference]") {
  // (10,10),(18,10),(10,18), Q = 1. Fringe box [ceil(10-1), floor(18+1)] = [9..19].
  // Column x = 9 and row y = 9 have D = -1 exactly: not > -1, so excluded.
  // Kept: x >= 10, y >= 10, x+y <= 29 (x+y = 29: D = -0.7071; 30: D = -1.414).
  // Count 55 as before.
  const Run r = run(tri_xy(10, 10, 18, 10, 10, 18), settings(1));
  CHECK(r.drawn);
  CHECK(r.samples.size() == 55);
  CHECK(r.pixels() == right_triangle_points(10, 10, 9));
  CHECK(r.at(9, 12) == nullptr);
  CHECK(r.at(12, 9) == nullptr);
  // Corner of the fringe (19, 10): D_hyp = -(19+10-28)/sqrt2 = -0.7071, other D = 9, 0.
  REQUIRE(r.at(19, 10) != nullptr);
  CHECK(r.at(19, 10)->nf == Approx(0.2928932188134524));
}

TEST_CASE("reference Q=1/2 shrinks the fringe to D > -0.5", "[reference]") {
  // (0,0),(8,0),(0,8), Q = 0.5: hypotenuse -(x+y-8)/sqrt2 > -0.5 -> x+y < 8.707:
  // only x+y <= 8, the same 45 pixels as Q = 0, all with D >= 0 -> nf = 1.
  const Run r = run(tri_xy(0, 0, 8, 0, 0, 8), settings(0.5));
  CHECK(r.samples.size() == 45);
  CHECK(r.pixels() == right_triangle_points(0, 0, 8));
  // Q = 2: -(x+y-8)/sqrt2 > -2 -> x+y < 8 + 2.83 = 10.83 -> x+y <= 10:
  // 11+10+...+1 = 66 pixels. At (5, 5): D = -2/sqrt2 = -1.41421,
  // Norm = 1 - 1.41421/2 = 0.29289.
  const Run r2 = run(tri_xy(0, 0, 8, 0, 0, 8), settings(2));
  CHECK(r2.samples.size() == 66);
  CHECK(r2.pixels() == right_triangle_points(0, 0, 10));
  REQUIRE(r2.at(5, 5) != nullptr);
  CHECK(r2.at(5, 5)->nf == Approx(0.2928932188134524));
  // At (4, 5): D = -1/sqrt2 = -0.70711, Norm = 1 - 0.35355 = 0.64645.
  CHECK(r2.at(4, 5)->nf == Approx(0.6464466094067263));
}

TEST_CASE("reference nf multiplies the clamped T plane into the coverage", "[reference]") {
  // T = 1 at (8,0), 0 at (0,0) and (0,8): T(x, y) = x/8.
  const Triangle t = tri(vtx(0, 0, 0, 0, 0, 1000, 0), vtx(8, 0, 0, 0, 0, 1000, 1), vtx(0, 8, 0, 0, 0, 1000, 0));
  const Run r = run(t, settings(1));
  // (4, 2) inside: T = 0.5, Norm = 1 -> nf = 0.5 -> 128 in 1.8.
  REQUIRE(r.at(4, 2) != nullptr);
  CHECK(r.at(4, 2)->t == Approx(0.5));
  CHECK(r.at(4, 2)->nf == Approx(0.5));
  CHECK(quantize_reference(*r.at(4, 2)).nf == 128);
  // (9, 0) in the fringe: T = 9/8 = 1.125 is clamped to 1; D_hyp = -0.70711 -> nf = 0.29289.
  REQUIRE(r.at(9, 0) != nullptr);
  CHECK(r.at(9, 0)->t == Approx(1.125));
  CHECK(r.at(9, 0)->nf == Approx(0.2928932188134524));
  // T = 1 - (x+y)/8 (opaque at the origin): at fringe (5, 4) T = -0.125 -> 0 -> nf = 0.
  const Triangle u = tri(vtx(0, 0, 0, 0, 0, 1000, 1), vtx(8, 0, 0, 0, 0, 1000, 0), vtx(0, 8, 0, 0, 0, 1000, 0));
  const Run ru = run(u, settings(1));
  REQUIRE(ru.at(5, 4) != nullptr);
  CHECK(ru.at(5, 4)->t == Approx(-0.125));
  CHECK(ru.at(5, 4)->nf == 0.0);
}

TEST_CASE("reference thin sliver without lattice points emits nothing but counts as drawn", "[reference]") {
  // y spans only 10.5 .. 10.7: no integer row, so no lattice point is inside.
  const Run r = run(tri_xy(10.1, 10.5, 300.2, 10.6, 10.1, 10.7), settings(0));
  CHECK(r.drawn);
  CHECK(r.samples.empty());
  // A sliver inside one pixel cell: x in 0.2..0.8, y in 0.1..0.9.
  const Run r2 = run(tri_xy(0.2, 0.1, 0.8, 0.3, 0.5, 0.9), settings(0));
  CHECK(r2.drawn);
  CHECK(r2.samples.empty());
}

TEST_CASE("reference triangle with a horizontal edge has the hand-counted rows", "[reference]") {
  // (2,2),(10,2),(6,6), Q = 0: left edge x = y, right edge x = 12 - y.
  // Row y: x = y .. 12 - y -> y=2: 2..10 (9), y=3: 3..9 (7), y=4: 4..8 (5),
  // y=5: 5..7 (3), y=6: 6 (1). Total 25.
  const Run r = run(tri_xy(2, 2, 10, 2, 6, 6), settings(0));
  CHECK(r.drawn);
  PixelSet expect;
  for (int y = 2; y <= 6; ++y)
    for (int x = y; x <= 12 - y; ++x) expect.insert({x, y});
  REQUIRE(expect.size() == 25);
  CHECK(r.pixels() == expect);
  std::map<int, int> rows;
  for (const ReferenceSample& s : r.samples) ++rows[s.y];
  CHECK(rows == std::map<int, int>{{2, 9}, {3, 7}, {4, 5}, {5, 3}, {6, 1}});
}

TEST_CASE("reference Gouraud colour and depth match hand-worked planes", "[reference]") {
  // R = 0 at (0,0), 255 at (8,0), 0 at (0,8) -> R = 255 x / 8.
  // G = 0, 0, 200 -> G = 25 y. B = 77 everywhere.
  // Z = 1000, 2000, 3000 -> Z = 1000 + 125 x + 250 y.
  const Triangle t = tri(vtx(0, 0, 0, 0, 77, 1000), vtx(8, 0, 255, 0, 77, 2000), vtx(0, 8, 0, 200, 77, 3000));
  const Run r = run(t, settings(0));
  // (4, 2): R = 127.5, G = 50, B = 77, Z = 1000 + 500 + 500 = 2000.
  const ReferenceSample* s = r.at(4, 2);
  REQUIRE(s != nullptr);
  CHECK(s->r == Approx(127.5));
  CHECK(s->g == Approx(50.0));
  CHECK(s->b == Approx(77.0));
  CHECK(s->z == Approx(2000.0));
  const Pixel p = quantize_reference(*s);
  CHECK(p.x == 4);
  CHECK(p.y == 2);
  CHECK(p.r == 127);  // floor(127.5)
  CHECK(p.g == 50);
  CHECK(p.b == 77);
  CHECK(p.z == 2000);
  CHECK(p.nf == 256);
  // (1, 6): R = 255/8 = 31.875 -> 31; G = 150; Z = 1000 + 125 + 1500 = 2625.
  const ReferenceSample* s2 = r.at(1, 6);
  REQUIRE(s2 != nullptr);
  CHECK(s2->r == Approx(31.875));
  CHECK(quantize_reference(*s2).r == 31);
  CHECK(quantize_reference(*s2).g == 150);
  CHECK(quantize_reference(*s2).z == 2625);
  // The vertices carry their own values: (8, 0) R = 255, (0, 8) G = 200.
  CHECK(r.at(8, 0)->r == Approx(255.0));
  CHECK(r.at(0, 8)->g == Approx(200.0));
}

TEST_CASE("quantize_reference truncates and saturates like the EP outputs", "[reference]") {
  ReferenceSample s;
  s.x = 3;
  s.y = 9;
  s.r = 17.99;    // -> 17 (truncation)
  s.g = -3.2;     // -> 0
  s.b = 286.875;  // -> 255
  s.z = 70000;    // -> 65535
  s.nf = 0.999;   // 255.744 -> 255
  Pixel p = quantize_reference(s);
  CHECK(p.x == 3);
  CHECK(p.y == 9);
  CHECK(p.r == 17);
  CHECK(p.g == 0);
  CHECK(p.b == 255);
  CHECK(p.z == 65535);
  CHECK(p.nf == 255);
  s.z = -5;      // -> 0
  s.nf = 1.0;    // -> 256
  s.r = 255.0;   // -> 255
  p = quantize_reference(s);
  CHECK(p.z == 0);
  CHECK(p.nf == 256);
  CHECK(p.r == 255);
  s.nf = std::nan("");  // -> 0
  CHECK(quantize_reference(s).nf == 0);
}

TEST_CASE("reference pixel set does not depend on the vertex order", "[reference]") {
  const std::vector<std::array<std::pair<double, double>, 3>> tris = {
      {{{0, 0}, {8, 0}, {0, 8}}},
      {{{2, 2}, {10, 2}, {6, 6}}},
      {{{3.3, 1.7}, {20.9, 6.2}, {7.1, 15.4}}},
  };
  for (double q : {0.0, 0.5, 1.0}) {
    for (const auto& v : tris) {
      const Run ref = run(tri_xy(v[0].first, v[0].second, v[1].first, v[1].second, v[2].first, v[2].second),
                          settings(q));
      REQUIRE(!ref.samples.empty());
      // All six orders (three of each winding).
      std::array<int, 3> idx{0, 1, 2};
      do {
        const auto& a = v[idx[0]];
        const auto& b = v[idx[1]];
        const auto& c = v[idx[2]];
        const Run o = run(tri_xy(a.first, a.second, b.first, b.second, c.first, c.second), settings(q));
        CHECK(o.drawn);
        CHECK(o.pixels() == ref.pixels());
        for (const ReferenceSample& s : o.samples) {
          const ReferenceSample* t = ref.at(s.x, s.y);
          REQUIRE(t != nullptr);
          CHECK(s.nf == Approx(t->nf).margin(1e-12));
        }
      } while (std::next_permutation(idx.begin(), idx.end()));
    }
  }
}

TEST_CASE("reference window clips the pixel set", "[reference]") {
  // (0,0),(8,0),(0,8), Q = 0, window 2..5 x 2..5: x, y in 2..5 and x + y <= 8:
  // x=2: y 2..5 (4), x=3: y 2..5 (4), x=4: y 2..4 (3), x=5: y 2..3 (2) -> 13.
  const Run r = run(tri_xy(0, 0, 8, 0, 0, 8), settings(0, Window{2, 2, 5, 5}));
  CHECK(r.drawn);
  PixelSet expect;
  for (int y = 2; y <= 5; ++y)
    for (int x = 2; x <= 5; ++x)
      if (x + y <= 8) expect.insert({x, y});
  REQUIRE(expect.size() == 13);
  CHECK(r.pixels() == expect);
}

TEST_CASE("reference triangle outside the window returns false and emits nothing", "[reference]") {
  // Wholly off screen (x, y >= 2000).
  const Run r = run(tri_xy(2000, 2000, 2100, 2000, 2000, 2100), settings(1));
  CHECK_FALSE(r.drawn);
  CHECK(r.samples.empty());
  // On screen but outside a small window (100..200): the triangle ends at x + y = 8.
  const Run r2 = run(tri_xy(0, 0, 8, 0, 0, 8), settings(0, Window{100, 100, 200, 200}));
  CHECK_FALSE(r2.drawn);
  CHECK(r2.samples.empty());
  // Above the screen (negative y).
  const Run r3 = run(tri_xy(10, -50, 60, -50, 30, -20), settings(0));
  CHECK_FALSE(r3.drawn);
  CHECK(r3.samples.empty());
}

TEST_CASE("reference degenerate triangles return false", "[reference]") {
  // Collinear: (0,0),(4,4),(8,8) has pv = 4*8 - 8*4 = 0.
  const Run r = run(tri_xy(0, 0, 4, 4, 8, 8), settings(1));
  CHECK_FALSE(r.drawn);
  CHECK(r.samples.empty());
  // Two coincident vertices.
  const Run r2 = run(tri_xy(5, 5, 5, 5, 20, 9), settings(0));
  CHECK_FALSE(r2.drawn);
  CHECK(r2.samples.empty());
  // Horizontal line.
  const Run r3 = run(tri_xy(1, 3, 50, 3, 20, 3), settings(0));
  CHECK_FALSE(r3.drawn);
}

}  // namespace girtd
