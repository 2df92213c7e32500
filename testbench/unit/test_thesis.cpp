// The thesis appendix's program (prepdda, DDApix, NF) on values worked by
// hand, and against a brute-force test of the same anchored lattice.
#include <catch2/catch.hpp>

#include <set>

#include "claims/thesis_losses.hpp"
#include "common/fixed_point.hpp"
#include "thesis/ddapix.hpp"
#include "thesis/thesis_preparer.hpp"

namespace girtd {
namespace {

ThesisVertex tv(double x, double y, double r) {
  ThesisVertex v;
  v.x = x;
  v.y = y;
  v.z = 0.25;
  v.r = r;
  v.t = 1;
  return v;
}

// Screen (KC = 63.5): (0, 0.25) -> (63.5, 31.75); (-0.5, -0.25) -> (31.75, 63.5);
// (0.5, -0.25) -> (95.25, 63.5): apex up, all exact in float.
std::array<ThesisVertex, 3> apex_up() { return {tv(0, 0.25, 1), tv(-0.5, -0.25, 0), tv(0.5, -0.25, 0)}; }

}  // namespace

TEST_CASE("thesis ftol truncates toward zero", "[thesis]") {
  CHECK(thesis_ftol(1.7f) == 1);
  CHECK(thesis_ftol(-1.7f) == -1);
  CHECK(thesis_ftol(-0.2f) == 0);
}

TEST_CASE("thesis NF: Norm bytes, T saturation, high-byte products", "[thesis]") {
  const int64_t one = 65536;
  // D1 = -0.5: high word -1, top fraction byte 0x80 = D + 1 = 0.5.
  CHECK(thesis_nf(-one / 2, one, one, one) == 128);
  // D1 = -0.5 and T = 0.5: (128 x 128) >> 8 = 64.
  CHECK(thesis_nf(-one / 2, one, one, one / 2) == 64);
  // D2 = -0.75 (byte 0x40) then D3 = -0.5 (0x80): 64 then (128 x 64) >> 8 = 32.
  CHECK(thesis_nf(one, -3 * one / 4, -one / 2, one) == 32);
  CHECK(thesis_nf(-one - 1, one, one, one) == 0);  // D < -1: outside
  CHECK(thesis_nf(one, one, one, -1) == 0);        // T < 0
  CHECK(thesis_nf(one, one, one, 3 * one) == 256); // T >= 1 counts as 1
  CHECK(thesis_nf(-one, one, one, one) == 0);      // D = -1 exactly: D + 1 = 0
}

TEST_CASE("thesis prepdda: winding, start at the top vertex, limits one pixel wider", "[thesis]") {
  const Params p = Params::defaults().with_thesis_formats();
  const auto d = thesis_prepare(apex_up(), p);
  REQUIRE(d);
  CHECK(d->x0 == 63);  // (int) 63.5
  CHECK(d->y0 == 31);  // (int) 31.75
  CHECK(d->xmin == 30);  // (int)(31.75 - 1)
  CHECK(d->xmax == 96);  // (int)(95.25 + 1)
  CHECK(d->ymax == 64);  // (int)(63.5 + 1)
  // The start is the apex: on edges 1 and 3 (D = 0), 31.75 px above edge 2.
  CHECK(std::abs(d->ep[kEpD1].v) <= 2);
  CHECK(std::abs(d->ep[kEpD3].v) <= 2);
  CHECK(d->ep[kEpD2].v == 2080768);  // 31.75 x 65536
  // Interior positive: edge 1 has outward normal up-left, so D1 grows to the right and down.
  CHECK(d->ep[kEpD1].dx > 0);
  CHECK(d->ep[kEpD1].dy > 0);
  CHECK(d->ep[kEpR].v == 16777216);  // r = 1 at the apex: 2^24
}

TEST_CASE("thesis prepdda drops a triangle with no area and one below the screen", "[thesis]") {
  const Params p = Params::defaults().with_thesis_formats();
  CHECK_FALSE(thesis_prepare({tv(0, 0, 0), tv(0.5, 0, 0), tv(-0.5, 0, 0)}, p));  // one row: pv = 0 exactly
  CHECK_FALSE(thesis_prepare({tv(0, -0.8, 0), tv(0.2, -0.9, 0), tv(-0.2, -0.9, 0)}, p));
}

TEST_CASE("DDApix emits every pixel of the anchored lattice with D >= -1, once", "[thesis]") {
  const Params p = Params::defaults().with_thesis_formats();
  const auto d = thesis_prepare(apex_up(), p);
  REQUIRE(d);
  std::multiset<std::pair<int, int>> emitted;
  DdaPix(p, ThesisInside::kProgram).run(*d, [&](const DdaEmit& e) { emitted.insert({e.pixel.x, e.pixel.y}); });
  std::set<std::pair<int, int>> expected;
  for (int y = d->y0; y <= d->ymax; ++y)
    for (int x = d->xmin; x <= d->xmax; ++x) {
      bool in = true;
      for (int e = kEpD1; e <= kEpD3; ++e)
        in = in && d->ep[e].v + int64_t(x - d->x0) * d->ep[e].dx + int64_t(y - d->y0) * d->ep[e].dy >= -65536;
      if (in) expected.insert({x, y});
    }
  for (const auto& px : expected) CHECK(emitted.count(px) == 1);
  // An apex-up triangle about 64 px wide and 32 high: roughly half of 64 x 32 plus the fringe.
  CHECK(expected.size() > 1000);
}

TEST_CASE("DDApix loses pixels with a sharp inside test, never with its own D >= -1", "[thesis]") {
  const Params p = Params::defaults();
  const ThesisLossSample program = measure_thesis_losses(p, ThesisInside::kProgram, 400, 5);
  const ThesisLossSample sharp = measure_thesis_losses(p, ThesisInside::kSharp, 400, 5);
  CHECK(program.triangles > 350);
  CHECK(program.triangles_losing == 0);
  CHECK(sharp.triangles_losing > 0);
}

}  // namespace girtd
