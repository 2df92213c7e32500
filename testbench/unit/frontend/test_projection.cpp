// View transform conventions, the screen map and the Zp map of §3.
#include <catch2/catch.hpp>

#include <cmath>

#include "frontend/projection.hpp"
#include "frontend/view_transform.hpp"

using namespace girtd;

TEST_CASE("Zp: Zmin -> 0, Zmax -> 65534, affine in 1/Zs", "[frontend]") {
  const DepthMap d(2, 10, 65534);
  CHECK(d.zp(2) == 0);
  CHECK(d.zp(10) == Approx(65534));
  // Zs = 4: 10/8 x (1 - 2/4) x 65534 = 1.25 x 0.5 x 65534 = 40958.75
  CHECK(d.zp(4) == Approx(40958.75));
  // Zmin == Zmax (one depth in the frame): everything at 0.
  CHECK(DepthMap(3, 3, 65534).zp(3) == 0);
}

TEST_CASE("projection: Xp = Xs/Zs D/S, Yp = Ys/Zs D/S", "[frontend]") {
  // (2, -1, 4) with D/S = 2: Xp = 2/4 x 2 = 1, Yp = -1/4 x 2 = -0.5.
  const PlanePoint p = project({2, -1, 4}, 2);
  CHECK(p.xp == 1);
  CHECK(p.yp == -0.5);
  // 90 deg field of view (D/S = 1): the 45 deg ray lands on the plane's edge.
  CHECK(project({-3, 3, 3}, d_over_s_for_fov(90)).xp == Approx(-1));
}

TEST_CASE("screen map: -1 and +1 on the first and last pixel centres, y down", "[frontend]") {
  const ScreenMap m{1024, 1024};
  CHECK(m.x(-1) == 0);
  CHECK(m.x(1) == 1023);
  CHECK(m.x(0) == 511.5);
  CHECK(m.y(1) == 0);  // top of the projection plane is row 0
  CHECK(m.y(-1) == 1023);
}

TEST_CASE("view transform: look-at and the three-angle convention", "[frontend]") {
  // 90 deg field of view: D/S = 1/tan 45 = 1.
  CHECK(d_over_s_for_fov(90) == Approx(1));
  const Camera la = *camera_look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90);
  // The origin is 5 straight ahead.
  const Vec3 s = to_camera_space(la, {0, 0, 0});
  CHECK(s.x == Approx(0).margin(1e-9));
  CHECK(s.z == Approx(5));
  // World (1, 2, 0): right 1, up 2.
  const Vec3 t = to_camera_space(la, {1, 2, 0});
  CHECK(t.x == Approx(1));
  CHECK(t.y == Approx(2));
  CHECK(!camera_look_at({0, 0, 0}, {0, 5, 0}, {0, 1, 0}, 60));  // up along the view direction

  // Angles 0: looking along -Z, up +Y: the same camera as the look-at above.
  const Camera a0 = camera_from_angles({0, 0, 5}, 0, 0, 0, 90);
  CHECK(to_camera_space(a0, {1, 2, 0}).x == Approx(1));
  CHECK(to_camera_space(a0, {1, 2, 0}).z == Approx(5));
  // Yaw 90 turns left: forward becomes -X, so a point at x = -3 is 3 ahead.
  const Camera yaw = camera_from_angles({0, 0, 0}, 90, 0, 0, 90);
  CHECK(to_camera_space(yaw, {-3, 0, 0}).z == Approx(3));
  // Pitch 90 looks up: a point above is ahead.
  const Camera pitch = camera_from_angles({0, 0, 0}, 0, 90, 0, 90);
  CHECK(to_camera_space(pitch, {0, 4, 0}).z == Approx(4));
  // Roll 90 (counter-clockwise seen from behind): the camera's right points to world +Y,
  // so a point at world +Y appears to the right.
  const Camera roll = camera_from_angles({0, 0, 0}, 0, 0, 90, 90);
  CHECK(to_camera_space(roll, {0, 1, -5}).x == Approx(1));
}
