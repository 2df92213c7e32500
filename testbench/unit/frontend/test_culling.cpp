// Culling in front of lighting: the view volume of object culling against
// hand-worked distances, and what the front end counts and keeps with it.
#include <catch2/catch.hpp>

#include "frontend/front_end.hpp"
#include "frontend/object_culling.hpp"

using namespace girtd;

namespace {

// The default camera: at the origin looking along world -Z (Zs = -z), up +Y;
// D/S = 1 is a 90 degree field of view.
Camera camera() {
  Camera c;
  c.d_over_s = 1;
  return c;
}

ViewVolume volume(double margin_px) { return ViewVolume(camera(), 0.1, ScreenMap{1024, 1024}, Window{}, margin_px); }

BoundingSphere sphere(double x, double y, double z, double r) { return {Vec3{x, y, z}, r}; }

// A unit square facing the camera (counter-clockwise seen from +Z) centred on (x, y, z).
WorldPolygon square(double x, double y, double z, int surface = 0) {
  return {surface, {{x - 0.5, y - 0.5, z}, {x + 0.5, y - 0.5, z}, {x + 0.5, y + 0.5, z}, {x - 0.5, y + 0.5, z}}, 0};
}

WorldFrame frame_of(std::vector<WorldPolygon> polygons, std::vector<WorldObject> objects) {
  WorldFrame f;
  f.camera = camera();
  f.focal_distance = 0.1;
  f.surfaces.resize(2);
  f.surfaces[1].t_min = 0.2;  // surface 1 is transparent
  f.surfaces[1].t_max = 0.6;
  f.lights.ambient = 0.5;
  f.polygons = std::move(polygons);
  f.objects = std::move(objects);
  return f;
}

}  // namespace

TEST_CASE("object culling: a sphere against the sides of the view volume, worked by hand", "[frontend][culling]") {
  // Margin 2 px: the right side is Xp = 2 (1023 + 2)/1023 - 1 = 1.0039101, its
  // unit normal (1, 0, -1.0039101)/1.4169861. A centre at Xs = 11.5, Zs = 10
  // lies (11.5 - 10.039101)/1.4169861 = 1.0310 outside it.
  const ViewVolume v = volume(2);
  CHECK_FALSE(v.misses(sphere(0, 0, -10, 1)));     // straight ahead
  CHECK(v.misses(sphere(20, 0, -10, 1)));          // Xp = 2: far right
  CHECK(v.misses(sphere(11.5, 0, -10, 1.03)));     // 1.0310 > 1.03
  CHECK_FALSE(v.misses(sphere(11.5, 0, -10, 1.04)));  // it reaches in
  CHECK(v.misses(sphere(0, 11.5, -10, 1.03)));     // the top side is the same distance away
  CHECK(v.misses(sphere(-11.5, -11.5, -10, 1.03)));
  // A wider margin moves the side out: Xp = 2 (1023 + 40)/1023 - 1 = 1.0782,
  // distance (11.5 - 10.782)/1.4686 = 0.489.
  CHECK(volume(40).misses(sphere(11.5, 0, -10, 0.48)));
  CHECK_FALSE(volume(40).misses(sphere(11.5, 0, -10, 0.5)));
}

TEST_CASE("object culling: the near plane Zs = C", "[frontend][culling]") {
  const ViewVolume v = volume(2);
  CHECK(v.misses(sphere(0, 0, 5, 1)));              // behind the camera: Zs = -5
  CHECK(v.misses(sphere(0, 0, -0.05, 0.0499)));     // Zs + r < C: nothing at Zs > C (touching C is kept)
  CHECK_FALSE(v.misses(sphere(0, 0, -0.05, 0.06)));  // pokes through C
  // The same test for a polygon's corners: all behind, or all beyond one side.
  CHECK(v.misses(std::vector<Vec3>{{0, 0, 1}, {1, 0, 1}, {0, 1, 0.5}}));
  CHECK(v.misses(std::vector<Vec3>{{20, 0, -10}, {30, 0, -10}, {20, 5, -10}}));
  // Beyond the right side and beyond the top, but no one side has every corner.
  CHECK_FALSE(v.misses(std::vector<Vec3>{{20, 0, -10}, {0, 20, -10}, {20, 20, -10}}));
}

TEST_CASE("bounding sphere: box centre, farthest corner", "[frontend][culling]") {
  const std::vector<WorldPolygon> p{square(0, 0, -5), square(3, 0, -5)};
  const BoundingSphere s = bounding_sphere(p, WorldObject{0, 2});
  // Box x -0.5..3.5, y -0.5..0.5: centre (1.5, 0, -5), radius sqrt(2^2 + 0.5^2).
  CHECK(s.centre.x == Approx(1.5));
  CHECK(s.centre.z == Approx(-5));
  CHECK(s.radius == Approx(std::sqrt(4.25)));
}

TEST_CASE("front end: object culling removes what cannot be drawn and changes no triangle", "[frontend][culling]") {
  // Object 0 ahead at two depths, object 1 (two squares) far to the right and
  // nearer and farther than object 0 (without the window test of the depth
  // range they would widen it and move every Zp), object 2 behind.
  const WorldFrame f = frame_of({square(0, 0, -5), square(0.5, 0, -8), square(40, 0, -4), square(60, 0, -12),
                                 square(0, 0, 5)},
                                {{0, 2}, {2, 2}, {4, 1}});
  FrontEnd plain(ScreenMap{1024, 1024}, 65534);
  FrontEndOptions on;
  on.cull_objects = true;
  FrontEnd culled(ScreenMap{1024, 1024}, 65534, on);
  const std::vector<Triangle> a = plain.run_frame(f, Window{}), b = culled.run_frame(f, Window{});
  REQUIRE(a.size() == 4);
  REQUIRE(b.size() == a.size());
  for (size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < 3; ++k) {  // the same depth range, so the same Zp
      CHECK(a[i].v[k].x == b[i].v[k].x);
      CHECK(a[i].v[k].z == b[i].v[k].z);
    }
  // Zmin = 5, Zmax = 8 (object 0 alone): the nearer square's corners map to 0,
  // the farther's to P.
  CHECK(std::min({a[0].v[0].z, a[3].v[0].z}) == 0);
  CHECK(std::max({a[0].v[0].z, a[3].v[0].z}) == Approx(65534));
  const FrontendCounts c = culled.counts();
  CHECK(c.polygons == 5);
  CHECK(c.objects == 3);
  CHECK(c.objects_culled == 2);
  CHECK(c.object_culled_polygons == 3);
  CHECK(c.object_culled_corners == 12);
  CHECK(plain.counts().objects_culled == 0);
  CHECK(plain.counts().clipped_away == 1);
  CHECK(plain.counts().discarded_off_window == 4);
}

TEST_CASE("front end: a forced back-face cull keeps transparent surfaces' back faces", "[frontend][culling]") {
  // Seen from behind (the camera looks along -Z, the squares face +Z... turned
  // round by reversing them): a back face of the opaque surface 0 and one of
  // the transparent surface 1.
  WorldPolygon back0 = square(-1, 0, -5, 0), back1 = square(1, 0, -5, 1);
  std::reverse(back0.p.begin(), back0.p.end());
  std::reverse(back1.p.begin(), back1.p.end());
  const WorldFrame f = frame_of({back0, back1}, {});
  FrontEndOptions always;
  always.cull_back_faces_always = true;
  FrontEnd fe(ScreenMap{1024, 1024}, 65534, always);
  CHECK(fe.run_frame(f, Window{}).size() == 2);  // the transparent square's two triangles
  CHECK(fe.counts().culled == 1);
  CHECK(fe.counts().back_faces_exempt == 1);
  CHECK(fe.counts().exempt_surfaces == std::set<int>{1});
  // The input's own cull flag culls both: it asked for it.
  WorldFrame asked = f;
  asked.cull_back_faces = true;
  FrontEnd fe2(ScreenMap{1024, 1024}, 65534, always);
  CHECK(fe2.run_frame(asked, Window{}).empty());
  CHECK(fe2.counts().culled == 2);
  CHECK(fe2.counts().back_faces_exempt == 0);
}

TEST_CASE("front end: pruning skips the lighting of polygons out of view, nothing else", "[frontend][culling]") {
  // One square ahead, one far right, one behind; lit by ambient light only.
  const WorldFrame f = frame_of({square(0, 0, -5), square(40, 0, -5), square(0, 0, 5)}, {});
  FrontEndOptions prune;
  prune.prune_lighting_out_of_view = true;
  FrontEndStages pruned(ScreenMap{1024, 1024}, 65534, prune), full(ScreenMap{1024, 1024}, 65534);
  pruned.begin_frame(f, Window{}, 1);
  full.begin_frame(f, Window{}, 1);
  // Ambient 0.5 of a grey 200 surface: 100 in view; the pruned run leaves
  // the two out of view unlit (0), the full run lights them too.
  CHECK(pruned.light(0)->v[0].r == Approx(100));
  CHECK(pruned.light(1)->v[0].r == 0);
  CHECK(pruned.light(2)->v[0].r == 0);
  CHECK(full.light(1)->v[0].r == Approx(100));
  // And the front end's triangles and counts are the same either way.
  FrontEnd a(ScreenMap{1024, 1024}, 65534, prune), b(ScreenMap{1024, 1024}, 65534);
  const std::vector<Triangle> ta = a.run_frame(f, Window{}), tb = b.run_frame(f, Window{});
  REQUIRE(ta.size() == tb.size());
  for (size_t i = 0; i < ta.size(); ++i) CHECK(ta[i].v[1].r == tb[i].v[1].r);
  CHECK(a.counts().discarded_off_window == b.counts().discarded_off_window);
  CHECK(a.counts().clipped_away == b.counts().clipped_away);
}
