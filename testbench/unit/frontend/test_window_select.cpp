// §3 selection and window clip as the front end uses it (the shared
// select_start_point): the four cases, and the discards counted.
#include <catch2/catch.hpp>

#include "common/triangle_setup.hpp"
#include "frontend/front_end.hpp"
#include "frontend/view_transform.hpp"

using namespace girtd;

namespace {

std::optional<StartPoint> start(std::array<Vertex, 3> v, const Window& w) {
  Triangle t;
  t.v = v;
  return select_start_point(*setup_triangle(t), w);
}

Vertex at(double x, double y) { return Vertex{x, y, 0, 0, 0, 0, 1}; }

}  // namespace

TEST_CASE("window select: corner inside, vertex inside, only crossings, no candidate", "[frontend]") {
  const Window w{100, 100, 200, 200};
  // Window corner (100, 100) inside a big triangle: it is the start point.
  auto s = start({at(0, 0), at(500, 0), at(0, 500)}, w);
  REQUIRE(s);
  CHECK(s->x == 100);
  CHECK(s->y == 100);
  // Vertices (150, 120), (180, 190), (120, 170) all inside: the smallest y wins.
  s = start({at(150, 120), at(180, 190), at(120, 170)}, w);
  REQUIRE(s);
  CHECK(s->x == 150);
  CHECK(s->y == 120);
  // A wide flat triangle through the window with every vertex outside and the corner
  // outside it: only edge/border crossings. Edge (0, 140) -> (300, 140) crosses x = 100
  // and x = 200 at y = 140; the edge (300, 160) -> (0, 140) crosses x = 200 at
  // y = 140 + 40/3 = 153.3 and x = 100 at 146.7. Smallest y: 140, ties to the left: x = 100.
  s = start({at(0, 140), at(300, 140), at(300, 160)}, w);
  REQUIRE(s);
  CHECK(s->x == 100);
  CHECK(s->y == 140);
  // Entirely left of the window: no candidate, discarded.
  CHECK(!start({at(0, 120), at(50, 120), at(20, 180)}, w));
}

TEST_CASE("window select: the front end counts the triangles it discards", "[frontend]") {
  // Camera at the origin looking down -Z, 90 deg: D/S = 1. Two unit squares at Zs = 10,
  // one straight ahead and one far to the right (Xs = 50: Xp = 5, off the screen).
  WorldFrame f;
  f.camera = camera_from_angles({0, 0, 0}, 0, 0, 0, 90);
  f.focal_distance = 0.5;
  f.surfaces.resize(1);
  f.polygons.push_back({0, {{-1, -1, -10}, {1, -1, -10}, {1, 1, -10}, {-1, 1, -10}}, 1});
  f.polygons.push_back({0, {{49, -1, -10}, {51, -1, -10}, {51, 1, -10}, {49, 1, -10}}, 2});
  FrontEnd fe(ScreenMap{1024, 1024}, 65534);
  const auto out = fe.run_frame(f, Window{});
  CHECK(out.size() == 2);
  CHECK(fe.counts().triangles_made == 4);
  CHECK(fe.counts().discarded_off_window == 2);
  CHECK(fe.counts().triangles_out == 2);
}
