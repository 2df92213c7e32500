// Scene JSON, model import and the polygon trace level: what goes in, and
// the FILE:LINE errors for what must not.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "common/input_error.hpp"
#include "io/model_import.hpp"
#include "io/scene_reader.hpp"
#include "io/trace_reader.hpp"
#include "io/trace_writer.hpp"

using namespace girtd;

namespace {

const std::string kModels = std::string(GIRTD_SOURCE_DIR) + "/traces/models/";

std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = "/tmp/girtd_frontend_test_" + name;
  std::ofstream(path) << text;
  return path;
}

// The InputError's "FILE:LINE: what", or "" when nothing was thrown.
template <typename F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.formatted();
  }
  return "";
}

}  // namespace

TEST_CASE("model import: polygons stay polygons, corners are shared", "[frontend]") {
  const Mesh cube = import_model(kModels + "cube.obj");
  CHECK(cube.positions.size() == 8);
  REQUIRE(cube.polygons.size() == 6);
  CHECK(cube.polygons[0].size() == 4);
  const Mesh off = import_model(kModels + "cube.off");
  CHECK(off.polygons.size() == 6);
  // Binary STL repeats every corner: merged back to the sphere's 12 x 24 - ... = 266 positions
  // (2 poles + 11 rings x 24).
  const Mesh stl = import_model(kModels + "sphere.stl");
  CHECK(stl.positions.size() == 2 + 11 * 24);
  CHECK(stl.polygons.size() == 2 * 24 + 2 * 240);
  const Mesh ply = import_model(kModels + "sphere.ply");
  CHECK(ply.polygons.size() == 2 * 24 + 240);
}

TEST_CASE("model import: broken files are InputErrors naming the file", "[frontend]") {
  CHECK(error_of([] { import_model(temp_file("empty.obj", "")); }).find("empty file") != std::string::npos);
  CHECK(error_of([] { import_model(temp_file("idx.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")); }) != "");
  CHECK(error_of([] { import_model(temp_file("idx.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n")); }) != "");
  CHECK(error_of([] { import_model(temp_file("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")); })
            .find("NaN or infinite") != std::string::npos);
  // A count far beyond what the file could hold is refused before assimp allocates for it.
  CHECK(error_of([] { import_model(temp_file("huge.off", "OFF\n99999999999 1 0\n0 0 0\n")); }) ==
        "/tmp/girtd_frontend_test_huge.off:2: header claims 99999999999 vertices, more than the file's 26 bytes could hold");
}

TEST_CASE("scene: models, materials, camera and frames; unknown keys fail with their line", "[frontend]") {
  const std::string scene = temp_file("scene.json", R"({
  "girtd_scene": 1,
  "background": [10, 20, 30],
  "camera": {"eye": [0, 0, 8], "target": [0, 0, 0]},
  "materials": {"red": {"colour": [255, 0, 0], "n": 30, "t_min": 0.1, "t_max": 0.5}},
  "models": [{"name": "box", "file": ")" + kModels + R"(cube.obj", "material": "red", "scale": 0.5}],
  "frames": [{}, {"models": {"box": {"rotate_deg": [0, 45, 0]}}}]
})");
  const Trace t = read_scene(scene, Params::defaults());
  REQUIRE(t.frames.size() == 2);
  CHECK(t.level == TraceLevel::kPolygon);
  CHECK(t.frames[0].settings.background.b == 30);
  CHECK(t.frames[0].world.polygons.size() == 6);
  CHECK(t.frames[0].world.surfaces.size() == 6);  // 90 deg edges > the 60 deg crease: 6 flat surfaces
  CHECK(t.frames[0].world.surfaces[0].r == 255);
  CHECK(t.frames[0].world.focal_distance == SceneDefaults::kFocalDistance);
  // Scale 0.5: the cube's corners at +-0.5; frame 1 turned 45 deg: a corner at x = 0.5 sqrt 2.
  double max_x0 = 0, max_x1 = 0;
  for (const WorldPolygon& p : t.frames[0].world.polygons)
    for (const Vec3& v : p.p) max_x0 = std::max(max_x0, v.x);
  for (const WorldPolygon& p : t.frames[1].world.polygons)
    for (const Vec3& v : p.p) max_x1 = std::max(max_x1, v.x);
  CHECK(max_x0 == Approx(0.5));
  CHECK(max_x1 == Approx(0.5 * std::sqrt(2.0)));

  const std::string bad = temp_file("bad.json", "{\n  \"girtd_scene\": 1,\n  \"models\": [\n    {\"file\": \"x.obj\",\n     \"colour\": 3}\n  ]\n}\n");
  CHECK(error_of([&] { read_scene(bad, Params::defaults()); }).rfind(bad + ":5: unknown key \"colour\"", 0) == 0);
  const std::string syntax = temp_file("syntax.json", "{\n  \"girtd_scene\": 1,\n  \"q\": ,\n}\n");
  CHECK(error_of([&] { read_scene(syntax, Params::defaults()); }).rfind(syntax + ":3: invalid JSON", 0) == 0);
  const std::string range = temp_file("range.json", "{\"girtd_scene\": 1,\n\"materials\": {\"m\": {\"cre\": [0, 0, 0, 0, 0, 0, 2]}},\n\"models\": []}\n");
  CHECK(error_of([&] { read_scene(range, Params::defaults()); }).rfind(range + ":2: ", 0) == 0);
}

TEST_CASE("polygon trace: written and read back exactly", "[frontend]") {
  const Params params = Params::defaults();
  Trace t = scene_from_model(kModels + "star.obj", params);
  REQUIRE(t.frames.size() == 1);
  const std::string path = "/tmp/girtd_frontend_test_star.poly";
  {
    TraceWriter w(path, TraceLevel::kPolygon, params, "test");
    w.begin_frame(t.frames[0].settings);
    w.write(t.frames[0].world);
    w.commit();
  }
  const Trace back = read_trace(path, std::nullopt, params);
  CHECK(back.level == TraceLevel::kPolygon);
  const WorldFrame& a = t.frames[0].world;
  const WorldFrame& b = back.frames[0].world;
  REQUIRE(b.polygons.size() == 1);
  CHECK(b.polygons[0].p.size() == 10);
  CHECK(b.polygons[0].p[3].x == a.polygons[0].p[3].x);
  CHECK(b.camera.centre.z == a.camera.centre.z);
  CHECK(b.camera.d_over_s == a.camera.d_over_s);
  CHECK(b.focal_distance == a.focal_distance);
  CHECK(b.lights.directional.size() == 1);
  CHECK(b.surfaces[0].cre == a.surfaces[0].cre);

  std::istringstream bad("girtd-trace 1 polygon\nsurface 0 1 1 1 1 0 0 0 0 0 0 0 0 0\ncamera 0 0 0 1 0 0 0 1 0 0 0 -1 1\n"
                         "focal 0.1\npoly 0 4 0 0 0 1 0 0 1 1 0\n");
  CHECK(error_of([&] { read_trace(bad, "p.trace", std::nullopt, params); }).rfind("p.trace:5: 'poly' takes", 0) == 0);
  std::istringstream no_surface("girtd-trace 1 polygon\ncamera 0 0 0 1 0 0 0 1 0 0 0 -1 1\nfocal 0.1\npoly 0 3 0 0 0 1 0 0 1 1 0\n");
  CHECK(error_of([&] { read_trace(no_surface, "p.trace", std::nullopt, params); }).rfind("p.trace:4: SURFACE", 0) == 0);
}
