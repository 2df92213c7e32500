// The four cases of the §3 depth clip at Zs = C, attributes interpolated
// with the corrected weights.
#include <catch2/catch.hpp>

#include "frontend/depth_clip.hpp"

using namespace girtd;

namespace {

CameraVertex cv(double x, double y, double z, double r) {
  CameraVertex v;
  v.s = {x, y, z};
  v.r = r;
  v.g = 2 * r;
  v.b = 0;
  v.t = 1;
  return v;
}

}  // namespace

TEST_CASE("depth clip: P = (P1 (C - Zs2) + P2 (Zs1 - C)) / (Zs1 - Zs2)", "[frontend]") {
  // P1 at Zs 5 (r 100), P2 at Zs 1 (r 20), C = 2: weights (2 - 1) = 1 and (5 - 2) = 3, sum 4.
  // r = (100 x 1 + 20 x 3)/4 = 40; x from 8 and 0: (8 + 0)/4 = 2. (The swapped weights of
  // the thesis' print would give r = (100 x 3 + 20)/4 = 80, on the wrong side.)
  const CameraVertex p = depth_crossing(cv(8, 0, 5, 100), cv(0, 0, 1, 20), 2);
  CHECK(p.s.z == 2);
  CHECK(p.s.x == Approx(2));
  CHECK(p.r == Approx(40));
  CHECK(p.g == Approx(80));
  CHECK(p.created);
}

TEST_CASE("depth clip: the four triangle cases", "[frontend]") {
  const double c = 1;
  SECTION("0 in front: dropped") {
    CHECK(depth_clip({cv(0, 0, 0.5, 0), cv(1, 0, 1, 0), cv(0, 1, -3, 0)}, c).empty());
  }
  SECTION("3 in front: unchanged") {
    const auto out = depth_clip({cv(0, 0, 2, 0), cv(1, 0, 3, 0), cv(0, 1, 4, 0)}, c);
    REQUIRE(out.size() == 3);
    CHECK(out[1].s.z == 3);
    CHECK(!out[0].created);
  }
  SECTION("1 in front: a smaller triangle") {
    // A (0,0,3) r 90 in front; B (4,0,-1) r 10 and C' (0,4,-1) r 50 behind.
    // A-B at Zs 1: weights (1 - -1) = 2 and (3 - 1) = 2 -> midpoint: x 2, r 50.
    // C'-A at Zs 1: midpoint of A and C': y 2, r 70.
    const auto out = depth_clip({cv(0, 0, 3, 90), cv(4, 0, -1, 10), cv(0, 4, -1, 50)}, c);
    REQUIRE(out.size() == 3);
    CHECK(out[1].s.x == Approx(2));
    CHECK(out[1].r == Approx(50));
    CHECK(out[2].s.y == Approx(2));
    CHECK(out[2].r == Approx(70));
  }
  SECTION("2 in front: a quadrilateral") {
    // A (0,0,5) r 0 and B (4,0,5) r 40 in front, C' (0,4,-3) r 80 behind, C = 1.
    // B-C' at Zs 1: weights (1 - -3) = 4 and (5 - 1) = 4: x 2, y 2, r 60.
    // C'-A at Zs 1: x 0, y 2, r 40.
    const auto out = depth_clip({cv(0, 0, 5, 0), cv(4, 0, 5, 40), cv(0, 4, -3, 80)}, c);
    REQUIRE(out.size() == 4);
    CHECK(out[2].s.x == Approx(2));
    CHECK(out[2].s.y == Approx(2));
    CHECK(out[2].r == Approx(60));
    CHECK(out[3].s.x == Approx(0).margin(1e-9));
    CHECK(out[3].r == Approx(40));
    CHECK(out[3].s.z == 1);
  }
}
