// End to end: a lit sphere and a cube through the front end and the golden
// back end; eight named pixels against a separate floating-point evaluation
// of the same lighting (written out here, not the model's code), within 2 LSB.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/backend_registry.hpp"
#include "backends/render_session.hpp"
#include "frontend/front_end.hpp"
#include "frontend/vertex_normals.hpp"
#include "frontend/view_transform.hpp"

using namespace girtd;

namespace {

constexpr double kPi = 3.14159265358979323846;
const double kDs = 1.0 / std::tan(30.0 * kPi / 180.0);  // 60 deg field of view

struct V {
  double x, y, z;
};
V add(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V mul(V a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dotv(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V unit(V a) { return mul(a, 1 / std::sqrt(dotv(a, a))); }
Vec3 vec(V a) { return {a.x, a.y, a.z}; }

const V kLight = unit({0.3, 0.5, 1.0});
constexpr double kAmbient = 0.2, kIf = 0.7;
const V kSphereC{-1.5, 0.3, -7}, kCubeC{2.0, -0.4, -7.5};
constexpr double kSphereR = 1.6;
constexpr double kSphereRgb[3] = {60, 120, 220}, kCubeRgb[3] = {200, 60, 40};
constexpr double kCre = 0.25, kN = 5;

// The camera sits at the origin looking down -Z: Xs = x, Ys = y, Zs = -z.
struct Px {
  int x, y;
};
Px pixel_of(V p) {
  const double zs = -p.z;
  return {static_cast<int>(std::lround(511.5 * (1 + p.x / zs * kDs))),
          static_cast<int>(std::lround(511.5 * (1 - p.y / zs * kDs)))};
}

// Ambient + Lambert + Phong-style specular with a constant CRE, one light.
double expected(double reflectance, V n, V p, bool specular) {
  const double ni = std::max(0.0, dotv(n, kLight));
  double c = reflectance * (kAmbient + kIf * ni);
  if (specular && ni > 0) {
    const V r = add(mul(n, 2 * ni), mul(kLight, -1));
    const V e = unit(mul(p, -1));  // toward the camera at the origin
    c += 255 * kCre * std::pow(std::max(0.0, dotv(r, e)), kN) * kIf;
  }
  return std::min(255.0, c);
}

// Cube axes after turning it 35 deg about Y, then 25 deg about X.
V cube_axis(V a) {
  const double y = 35 * kPi / 180, x = 25 * kPi / 180;
  V b{std::cos(y) * a.x + std::sin(y) * a.z, a.y, -std::sin(y) * a.x + std::cos(y) * a.z};
  return {b.x, std::cos(x) * b.y - std::sin(x) * b.z, std::sin(x) * b.y + std::cos(x) * b.z};
}

WorldFrame scene() {
  WorldFrame f;
  f.camera = camera_from_angles({0, 0, 0}, 0, 0, 0, 60);
  f.focal_distance = 0.5;
  f.lights.ambient = kAmbient;
  f.lights.directional = {{vec(kLight), kIf}};
  Surface sphere;
  sphere.r = kSphereRgb[0], sphere.g = kSphereRgb[1], sphere.b = kSphereRgb[2];
  sphere.cre.fill(kCre);
  sphere.n = kN;
  f.surfaces.push_back(sphere);  // surface 0: the whole sphere, smooth
  const int nlat = 24, nlon = 48;
  auto sp = [&](int i, int j) {
    const double th = kPi * i / nlat, ph = 2 * kPi * j / nlon;
    return vec(add(kSphereC, mul(V{std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)}, kSphereR)));
  };
  for (int i = 0; i < nlat; ++i)
    for (int j = 0; j < nlon; ++j) {
      // Counter-clockwise from outside: (i, j), (i+1, j), (i+1, j+1), (i, j+1) turns the other way round.
      std::vector<Vec3> q = {sp(i, j), sp(i, j + 1), sp(i + 1, j + 1), sp(i + 1, j)};
      if (i == 0) q.erase(q.begin());               // north cap: triangles
      else if (i == nlat - 1) q.erase(q.begin() + 3);  // south cap
      f.polygons.push_back({0, q, 0, {}});
    }
  // Cube: six flat, matte surfaces (1..6) of the same material.
  Surface cube;
  cube.r = kCubeRgb[0], cube.g = kCubeRgb[1], cube.b = kCubeRgb[2];
  for (int k = 0; k < 3; ++k)
    for (int s : {-1, 1}) {
      V n{0, 0, 0}, u{0, 0, 0}, w{0, 0, 0};
      (k == 0 ? n.x : k == 1 ? n.y : n.z) = s;
      (k == 0 ? u.y : k == 1 ? u.z : u.x) = 1;
      (k == 0 ? w.z : k == 1 ? w.x : w.y) = 1;
      if (s < 0) std::swap(u, w);  // keep u x w = n: counter-clockwise from outside
      std::vector<Vec3> q;
      for (auto [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
        q.push_back(vec(add(kCubeC, cube_axis(add(n, add(mul(u, a), mul(w, b)))))));
      f.surfaces.push_back(cube);
      f.polygons.push_back({static_cast<int>(f.surfaces.size()) - 1, q, 0, {}});
    }
  return f;
}

}  // namespace

TEST_CASE("end to end: lit sphere and cube, eight pixels within 2 LSB", "[frontend]") {
  const Params params = Params::defaults();
  FrontEnd fe(ScreenMap{params.screen_width, params.screen_height}, params.depth_max_mapped);
  Trace trace;
  trace.path = "sphere_and_cube";
  TraceFrame frame;
  frame.settings.q = 0;  // no fringe: the pixels sampled are interior anyway
  frame.triangles = fe.run_frame(scene(), frame.settings.window);
  trace.frames.push_back(frame);
  FrameSource input(trace);
  const RenderOutput out = render_frames(backend_named("golden"), input, params, RenderOptions{});

  struct Named {
    const char* name;
    V point, normal;
    const double* rgb;
    bool specular;
  };
  std::vector<Named> probes;
  // Sphere: equator vertices facing the camera. Their averaged normal is the
  // radius exactly (the four quads around them are mirror images).
  for (int deg : {60, 75, 90, 105, 120}) {
    const double ph = deg * kPi / 180;
    const V n{std::cos(ph), 0, std::sin(ph)};
    probes.push_back({"sphere equator vertex", add(kSphereC, mul(n, kSphereR)), n, kSphereRgb, true});
  }
  // Cube: centres of the three faces turned toward the camera (-x, +y, +z of the cube:
  // e.g. +y turns to (0, cos 25, sin 25), whose dot with (-2, 0.4, 7.5) toward the camera is > 0).
  for (V a : {V{-1, 0, 0}, V{0, 1, 0}, V{0, 0, 1}}) {
    const V n = cube_axis(a);
    probes.push_back({"cube face centre", add(kCubeC, n), n, kCubeRgb, false});
  }
  REQUIRE(probes.size() == 8);
  for (const Named& p : probes) {
    const Px px = pixel_of(p.point);
    const size_t at = 3 * (static_cast<size_t>(px.y) * 1024 + static_cast<size_t>(px.x));
    for (int c = 0; c < 3; ++c) {
      const double want = expected(p.rgb[c], p.normal, p.point, p.specular);
      const int got = out.shown.rgb[at + static_cast<size_t>(c)];
      INFO(p.name << " at pixel (" << px.x << ", " << px.y << ") channel " << c << ": expected " << want << ", got " << got);
      CHECK(std::fabs(got - want) <= 2.0);
    }
  }
}

TEST_CASE("front end: culling removes the cube's back half, counts add up", "[frontend]") {
  WorldFrame f = scene();
  f.cull_back_faces = true;
  WorldFrame cube_only = f;
  cube_only.polygons.erase(cube_only.polygons.begin(), cube_only.polygons.end() - 6);
  FrontEnd cube_fe(ScreenMap{1024, 1024}, 65534);
  cube_fe.run_frame(cube_only, Window{});
  CHECK(cube_fe.counts().culled == 3);  // -x, +y, +z face the camera; +x, -y, -z do not

  FrontEnd fe(ScreenMap{1024, 1024}, 65534);
  fe.run_frame(f, Window{});
  const FrontendCounts c = fe.counts();
  CHECK(c.polygons == 24 * 48 + 6);
  // From a finite distance d a sphere of radius r shows a cap of (1 - r/d)/2 of its
  // area: (1 - 1.6/7.1)/2 = 39 %, so a bit over half its polygons are culled (more where
  // the cap holds the big equatorial quads).
  CHECK(c.culled > (1152 + 6) / 2);
  CHECK(c.culled < (1152 + 6) * 3 / 4);
  // Sphere: 96 cap triangles + 1056 quads -> 96 + 2 x 1056 = 2208; cube 12; the triangulator
  // sees only the polygons that survived.
  CHECK(c.triangles_made < (2208 + 12) * 6 / 10);
  CHECK(c.triangles_out + c.discarded_off_window + c.degenerate_triangles == c.triangles_made);
}

TEST_CASE("front end: depth clip through the near plane, non-planar polygon", "[frontend]") {
  WorldFrame f;
  f.camera = camera_from_angles({0, 1, 0}, 0, 0, 0, 90);
  f.focal_distance = 0.5;
  f.surfaces.resize(1);
  // A floor from behind the camera (z = +5) to z = -20: cut at Zs = 0.5.
  f.polygons.push_back({0, {{-5, 0, 5}, {5, 0, 5}, {5, 0, -20}, {-5, 0, -20}}, 1, {}});
  // Entirely behind: dropped.
  f.polygons.push_back({0, {{-1, 1, 3}, {1, 1, 3}, {0, 2, 3}}, 2, {}});
  // A twisted quad in front.
  f.polygons.push_back({0, {{-1, 1, -6}, {1, 1.5, -6}, {1, 3, -6}, {-1, 2.5, -5.5}}, 3, {}});
  FrontEnd fe(ScreenMap{1024, 1024}, 65534);
  const auto tris = fe.run_frame(f, Window{});
  const FrontendCounts c = fe.counts();
  CHECK(c.clipped == 1);
  CHECK(c.clipped_away == 1);
  CHECK(c.non_planar == 1);
  CHECK(c.triangles_made == 4);  // the clipped floor is still a quad: 2, the twisted quad 2
  // The clip made vertices at Zs = C = Zmin: they map to Zp = 0; the floor's far edge
  // (Zs = 20) is the frame's Zmax -> 65534.
  double zmin = 1e9, zmax = -1;
  for (const Triangle& t : tris)
    for (const Vertex& v : t.v) zmin = std::min(zmin, v.z), zmax = std::max(zmax, v.z);
  CHECK(zmin == 0);
  CHECK(zmax == Approx(65534));
  // made_edge: each quad's one diagonal, seen from both its triangles: 2 + 2.
  // The edge the clip made along Zs = C (both ends at Zp = 0) is a polygon
  // edge of the clipped floor: drawn in wire-frame, not made.
  CHECK(c.made_edges == 4);
  // The flags are the triangulator's output (run_frame hands on triangles
  // alone): the stages one by one, as the timed pipeline runs them.
  FrontEndStages st(ScreenMap{1024, 1024}, 65534);
  st.begin_frame(f, Window{}, 1.0);
  std::vector<FrontPolygon> held;
  for (size_t i = 0; i < f.polygons.size(); ++i)
    if (std::optional<FrontPolygon> lit = st.light(i)) {
      st.view(*lit);
      if (std::optional<FrontPolygon> kept = st.depth_clip(*lit)) {
        st.note_depths(*kept);
        held.push_back(*kept);
      }
    }
  const DepthMap depth = st.depth_map();
  int cut_edges = 0;
  for (const FrontPolygon& p : held)
    if (std::optional<ScreenPolygon> sp = st.project(p, depth))
      for (const SortableTriangle& t : st.triangulate(*sp).triangles)
        for (int e = 0; e < 3; ++e)
          if (t.ft.tri.v[e].z == 0 && t.ft.tri.v[(e + 1) % 3].z == 0) {
            ++cut_edges;
            CHECK_FALSE(t.ft.made_edge[e]);
          }
  CHECK(cut_edges == 1);
}

TEST_CASE("front end: a polygon without area is degenerate in world space, before culling", "[frontend]") {
  // Three points on one 3D line, seen by a turned camera: in camera space
  // rounding leaves the Newell normal non-zero, which the old exact test
  // let through (it drew a long line).
  const Vec3 p0{0.1, 0.2, -5}, d{0.37, 0.11, -0.53};
  const std::vector<Vec3> line = {p0, p0 + 0.3 * d, p0 + 0.7 * d};
  WorldFrame f;
  f.camera = camera_from_angles({0.3, -0.2, 1}, 17, 5, 3, 60);
  f.focal_distance = 0.1;
  f.surfaces.resize(1);
  std::vector<Vec3> seen;
  for (const Vec3& p : line) seen.push_back(to_camera_space(f.camera, p));
  REQUIRE(length(newell_normal(seen)) > 0);
  f.polygons.push_back({0, line, 1, {}});
  for (bool cull : {false, true}) {
    f.cull_back_faces = cull;
    FrontEnd fe(ScreenMap{1024, 1024}, 65534);
    CHECK(fe.run_frame(f, Window{}).empty());
    CHECK(fe.counts().degenerate_polygons == 1);
    CHECK(fe.counts().culled == 0);  // no area, no facing: not a back face
    CHECK(fe.counts().triangles_made == 0);
  }
  // A thin but real sliver (area / perimeter^2 = 1.25e-6) stays a polygon.
  f.cull_back_faces = false;
  f.polygons = {{0, {{0, 0, -5}, {1, 0, -5}, {0.5, 1e-5, -5}}, 2, {}}};
  FrontEnd fe(ScreenMap{1024, 1024}, 65534);
  fe.run_frame(f, Window{});
  CHECK(fe.counts().degenerate_polygons == 0);
  CHECK(fe.counts().triangles_made == 1);
}
