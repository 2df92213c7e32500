// The preparer against hand-worked derivatives, edge equations, limits and
// start points (§3, 4.3.3). D has 12 fraction bits, colour 9.
#include <catch2/catch.hpp>

#include <cmath>

#include <map>
#include <vector>

#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"

namespace girtd {
namespace {

Triangle tri(std::array<std::array<double, 3>, 3> xyr) {
  Triangle t;
  for (int i = 0; i < 3; ++i) {
    t.v[i].x = xyr[i][0];
    t.v[i].y = xyr[i][1];
    t.v[i].r = xyr[i][2];
    t.v[i].z = 500;
  }
  return t;
}

FrameSettings frame(double q, Window w = {}) {
  FrameSettings f;
  f.q = q;
  f.window = w;
  return f;
}

}  // namespace

// (0,0) R=0, (10,0) R=100, (0,20) R=40. Thesis formula, vertices as given:
// P'x = (100*20 - 40*0) / (10*20 - 0*0) = 10, P'y = (40*10 - 100*0) / 200 = 2.
TEST_CASE("preparer: colour derivatives by the thesis formula", "[preparer]") {
  const Params p = Params::defaults();
  DdaPreparer prep(p);
  DdaParams d;
  REQUIRE(prep.prepare(tri({{{0, 0, 0}, {10, 0, 100}, {0, 20, 40}}}), frame(0), d) == PrepareResult::kReady);
  CHECK(d.ep[kEpR].dx == 10 * 512);
  CHECK(d.ep[kEpR].dy == 2 * 512);
  CHECK(d.ep[kEpR].v == 0);  // start at the window corner (0,0), which is a vertex
  CHECK(d.ep[kEpT].v == 256 * 512);  // opaque: T = 1.0 on the 0..256 scale
  CHECK(d.ep[kEpZ].v == 500 * 256);
  CHECK(d.ep[kEpZ].dx == 0);
}

// Same triangle. Counter-clockwise on the y-down screen it is (0,0) (0,20) (10,0):
// edge (0,0)->(0,20): A = 20, B = 0 -> D = x; edge (0,20)->(10,0): A = -20,
// B = -10, C = 200, L = sqrt(500) -> D = (200 - 20x - 10y)/22.3607;
// edge (10,0)->(0,0): A = 0, B = 10 -> D = y.
TEST_CASE("preparer: edge distances and winding", "[preparer]") {
  const Params p = Params::defaults();
  DdaPreparer prep(p);
  DdaParams cw, ccw;
  REQUIRE(prep.prepare(tri({{{0, 0, 0}, {10, 0, 100}, {0, 20, 40}}}), frame(0), cw) == PrepareResult::kReady);
  REQUIRE(prep.prepare(tri({{{0, 0, 0}, {0, 20, 40}, {10, 0, 100}}}), frame(0), ccw) == PrepareResult::kReady);
  CHECK(cw == ccw);  // the preparer reorders the clockwise one
  CHECK(cw.ep[kEpD1] == EpInit{0, 4096, 0});  // D = x
  // 200/sqrt(500) = 8.944272 -> 36635.74 -> 36636; -20/sqrt(500) = -0.894427 ->
  // -3663.57 -> -3664; -10/sqrt(500) = -0.447214 -> -1831.79 -> -1832.
  CHECK(cw.ep[kEpD2] == EpInit{36636, -3664, -1832});
  CHECK(cw.ep[kEpD3] == EpInit{0, 0, 4096});  // D = y
  CHECK(cw.xmin == 0);
  CHECK(cw.xmax == 10);
  CHECK(cw.ymax == 20);
}

TEST_CASE("preparer: limits widen by Q and the start is the top vertex", "[preparer]") {
  const Params p = Params::defaults();
  DdaPreparer prep(p);
  DdaParams d;
  REQUIRE(prep.prepare(tri({{{100.4, 50.6, 0}, {80, 90, 0}, {120, 90, 0}}}), frame(1), d) ==
          PrepareResult::kReady);
  CHECK(d.y0 == 50);    // ceil(50.6 - 1)
  CHECK(d.x0 == 100);   // floor(100.4 + 0.5)
  CHECK(d.xmin == 79);  // ceil(80 - 1)
  CHECK(d.xmax == 121); // floor(120 + 1)
  CHECK(d.ymax == 91);  // floor(90 + 1)
}

TEST_CASE("preparer: start at the window corner when it is inside the triangle", "[preparer]") {
  const Params p = Params::defaults();
  DdaPreparer prep(p);
  DdaParams d;
  const Window w{5, 5, 100, 100};
  // (5,5): x = 5 >= 0, y = 5 >= 0, (200 - 100 - 50)/22.36 > 0: inside.
  REQUIRE(prep.prepare(tri({{{0, 0, 0}, {10, 0, 100}, {0, 20, 40}}}), frame(0, w), d) == PrepareResult::kReady);
  CHECK(d.x0 == 5);
  CHECK(d.y0 == 5);
  CHECK(d.ep[kEpR].v == (10 * 5 + 2 * 5) * 512);  // R(5,5) = 60
  CHECK(d.xmin == 5);
}

TEST_CASE("preparer: start at the leftmost crossing of the top border", "[preparer]") {
  const Params p = Params::defaults();
  DdaPreparer prep(p);
  DdaParams d;
  // Apex (100,-50) above the screen; the edges cross y = 0 at x = 100 - 50/3 =
  // 83.33 and 116.67: equal y, the smaller x wins.
  REQUIRE(prep.prepare(tri({{{100, -50, 0}, {50, 100, 0}, {150, 100, 0}}}), frame(0), d) == PrepareResult::kReady);
  CHECK(d.y0 == 0);
  CHECK(d.x0 == 83);
}

TEST_CASE("preparer: discards triangles with no area or outside the window", "[preparer]") {
  const Params p = Params::defaults();
  DdaPreparer prep(p);
  DdaParams d;
  CHECK(prep.prepare(tri({{{0, 0, 0}, {10, 10, 0}, {20, 20, 0}}}), frame(1), d) == PrepareResult::kDegenerate);
  CHECK(prep.prepare(tri({{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}}}), frame(1, Window{50, 50, 60, 60}), d) ==
        PrepareResult::kOffWindow);
  CHECK(prep.counts().degenerate == 1);
  CHECK(prep.counts().off_window == 1);
}

}  // namespace girtd

namespace girtd {
namespace {

// Emissions per lattice pixel of `tris` through the preparer and the DDA.
std::map<std::pair<int, int>, int> coverage(const Params& p, const std::vector<Triangle>& tris, double q,
                                            uint8_t interior = 0) {
  DdaPreparer prep(p);
  const DdaEngine dda(p);
  std::map<std::pair<int, int>, int> hits;
  for (Triangle t : tris) {
    t.interior_edges = interior;
    DdaParams d;
    if (prep.prepare(t, frame(q), d) != PrepareResult::kReady) continue;
    dda.run(d, [&](const DdaEmit& e) { ++hits[{e.pixel.x, e.pixel.y}]; });
  }
  return hits;
}

}  // namespace

// A 10 x 10 square on lattice corners, split on its diagonal: 121 lattice
// points in the closed square. As written (D >= 0) both triangles draw the
// 11 on the diagonal; with the top-left rule the square owns its left and
// top edges only, 10 x 10 points, each drawn once.
TEST_CASE("preparer: the top-left rule draws a shared diagonal once", "[preparer]") {
  const std::vector<Triangle> square = {tri({{{100, 100, 0}, {110, 100, 0}, {110, 110, 0}}}),
                                        tri({{{100, 100, 0}, {110, 110, 0}, {100, 110, 0}}})};
  const auto as_written = coverage(Params::defaults(), square, 0);
  CHECK(as_written.size() == 121);
  int twice = 0;
  for (const auto& [px, n] : as_written) twice += n == 2;
  CHECK(twice == 11);

  const Params top_left = Params::with_overrides({{"preparer", {{"fill_rule", "top_left"}}}}, "test");
  const auto once = coverage(top_left, square, 0);
  CHECK(once.size() == 100);
  for (const auto& [px, n] : once) {
    CHECK(n == 1);
    CHECK(px.first >= 100);
    CHECK(px.first <= 109);
    CHECK(px.second >= 100);
    CHECK(px.second <= 109);
  }
}

// With Q = 1 each triangle's fringe runs a pixel over the diagonal into its
// neighbour; an interior edge with edge flags has none: the diagonal's
// neighbourhood is drawn once (the outer edges keep their fringe).
TEST_CASE("preparer: edge flags take the fringe off an interior edge", "[preparer]") {
  const std::vector<Triangle> square = {tri({{{100, 100, 0}, {110, 100, 0}, {110, 110, 0}}}),
                                        tri({{{100, 100, 0}, {110, 110, 0}, {100, 110, 0}}})};
  const Params robust =
      Params::with_overrides({{"preparer", {{"fill_rule", "top_left"}, {"edge_flags", true}}}}, "test");
  // Edge 2 of the first triangle (v2 -> v0) and edge 0 of the second (v0 -> v1) are the diagonal.
  int overlapping = 0;
  for (const auto& [px, n] : coverage(Params::defaults(), square, 1)) overlapping += n > 1;
  CHECK(overlapping > 11);
  DdaPreparer prep(robust);
  const DdaEngine dda(robust);
  std::map<std::pair<int, int>, int> hits;
  const uint8_t diagonal[2] = {4, 1};
  for (int k = 0; k < 2; ++k) {
    Triangle t = square[k];
    t.interior_edges = diagonal[k];
    DdaParams d;
    REQUIRE(prep.prepare(t, frame(1), d) == PrepareResult::kReady);
    CHECK(d.hard_edges != 0);
    dda.run(d, [&](const DdaEmit& e) { ++hits[{e.pixel.x, e.pixel.y}]; });
  }
  int drawn_twice = 0;
  for (const auto& [px, n] : hits) drawn_twice += n > 1;
  CHECK(drawn_twice == 0);
}

// Corners a million pixels away: as written the D EPs (+-2048 px) cannot
// hold the start values (clamped, counted); with far edges as constants
// every edge that misses the window becomes D = 0 (inside everywhere).
TEST_CASE("preparer: far edges as constants", "[preparer]") {
  const Triangle huge = tri({{{-1e6, -1e6, 0}, {1e6, -1e6, 0}, {511.5, 1e6, 0}}});
  DdaParams d;
  const Params defaults = Params::defaults();  // the preparer keeps a reference
  DdaPreparer as_written(defaults);
  REQUIRE(as_written.prepare(huge, frame(0), d) == PrepareResult::kReady);
  CHECK(d.clamped);
  const Params far = Params::with_overrides({{"preparer", {{"far_edges", "constant"}}}}, "test");
  DdaPreparer prep(far);
  REQUIRE(prep.prepare(huge, frame(0), d) == PrepareResult::kReady);
  CHECK_FALSE(d.clamped);
  for (int e = kEpD1; e <= kEpD3; ++e) CHECK(d.ep[e] == EpInit{});
  CHECK(prep.counts().constant_edges == 3);
}

}  // namespace girtd

namespace girtd {

// A needle 0.2 px wide and 50 px long, red 0 and 255 at its base corners:
// dR/dx = 255 / 0.2 = 1,275 per px, dR/dy = 0. As computed, d/dx does not
// fit the colour EP (+-1,024: clamped) and the fringe wraps. Limited: the
// longest edge runs from (100, 100) to the tip (100.1, 150), u = (0.002,
// 1.0), so along it red rises 1,275 x 0.002 = 2.55 per px, and across it
// (n = (-1.0, 0.002)) falls 1,275 per px. With Q = 1 the DDA may emit in
// x 99..101 (the box) and rows 99..151; the centroid is (100.1, 116.67),
// red 127.5. The corner (101, 151) binds: along +34.33 px (red +87.5),
// across -0.831 px, so across is cut to (1,024 - 127.5 - 87.5) / 0.831 =
// 973 per px (less the walk's rounding margin, 56 steps of an LSB),
// and d/dx = 973 x 1.0 + 2.55 x 0.002 = 973.
TEST_CASE("preparer: steep attributes limited across a needle", "[preparer]") {
  const Triangle needle = tri({{{100, 100, 0}, {100.2, 100, 255}, {100.1, 150, 127.5}}});
  const Params as_computed = Params::defaults();
  const Params limited = Params::with_overrides({{"preparer", {{"steep_attributes", "limited"}}}}, "test");
  auto affected = [&needle](const Params& p, DdaParams& d, DdaPreparer& prep) {
    REQUIRE(prep.prepare(needle, frame(1), d) == PrepareResult::kReady);
    return DdaEngine(p).run(d, [](const DdaEmit&) {}).numerics.triangles_affected;
  };
  DdaParams d;
  DdaPreparer plain(as_computed);
  CHECK(affected(as_computed, d, plain) == 1);
  CHECK(d.clamped);
  CHECK(d.ep[kEpR].dx == as_computed.ep_color.raw_max());

  DdaPreparer cut(limited);
  CHECK(affected(limited, d, cut) == 0);
  CHECK_FALSE(d.clamped);
  CHECK(cut.counts().limited_planes == 1);  // G, B, T and Z are flat
  const double dx = double(d.ep[kEpR].dx) / 512, dy = double(d.ep[kEpR].dy) / 512;
  CHECK(dx == Approx(973).margin(1));
  const double cx = (100 + 100.2 + 100.1) / 3, cy = (100 + 100 + 150) / 3.0;
  const double at_centroid = double(d.ep[kEpR].v) / 512 + dx * (cx - d.x0) + dy * (cy - d.y0);
  CHECK(at_centroid == Approx(127.5).margin(0.05));
}

}  // namespace girtd

namespace girtd {

// A flat white triangle in a colour EP of 9 integer bits (+-256): 255 fits,
// but not with the walk's rounding margin below the top. No cut can help a
// plane whose own value does not fit: it is left as computed (R = 255 x 512
// raw, no derivative), not cut to nonsense.
TEST_CASE("preparer: steep attributes leave a plane alone that no cut can fit", "[preparer]") {
  Triangle flat = tri({{{10, 10, 255}, {1000, 10, 255}, {10, 760, 255}}});
  const Params narrow = Params::with_overrides(
      {{"ep", {{"color", {{"int_bits", 9}, {"frac_bits", 9}}}}}, {"preparer", {{"steep_attributes", "limited"}}}}, "test");
  DdaPreparer prep(narrow);
  DdaParams d;
  REQUIRE(prep.prepare(flat, frame(1), d) == PrepareResult::kReady);
  CHECK(prep.counts().limited_planes == 0);
  CHECK(d.ep[kEpR].v == 255 * 512);
  CHECK(d.ep[kEpR].dx == 0);
  CHECK(d.ep[kEpR].dy == 0);
}

}  // namespace girtd
