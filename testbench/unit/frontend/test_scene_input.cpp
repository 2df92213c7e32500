// Scene JSON, model import and the polygon trace level: what goes in, and
// the FILE:LINE errors for what must not.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "common/input_error.hpp"
#include "io/json_lines.hpp"
#include "io/model_import.hpp"
#include "io/scene_reader.hpp"
#include "io/trace_reader.hpp"
#include "io/trace_writer.hpp"
#include "input_test_support.hpp"

using namespace girtd;
using namespace girtd::test;

namespace {

// A model that must import without a warning.
Mesh import_clean(const std::string& path) {
  std::vector<std::string> warnings;
  Mesh mesh = import_model(path, warnings).mesh;
  CHECK(warnings.empty());
  return mesh;
}

}  // namespace

TEST_CASE("model import: polygons stay polygons, corners are shared", "[frontend]") {
  const Mesh cube = import_clean(kModels + "cube.obj");
  CHECK(cube.positions.size() == 8);
  REQUIRE(cube.polygon_count() == 6);
  CHECK(cube.polygon(0).size == 4);
  const Mesh off = import_clean(kModels + "cube.off");
  CHECK(off.polygon_count() == 6);
  // Binary STL repeats every corner: merged back to the sphere's 12 x 24 - ... = 266 positions
  // (2 poles + 11 rings x 24).
  const Mesh stl = import_clean(kModels + "sphere.stl");
  CHECK(stl.positions.size() == 2 + 11 * 24);
  CHECK(stl.polygon_count() == 2 * 24 + 2 * 240);
  const Mesh ply = import_clean(kModels + "sphere.ply");
  CHECK(ply.polygon_count() == 2 * 24 + 240);
}

TEST_CASE("model import: broken files are InputErrors naming the file", "[frontend]") {
  CHECK(error_of([] { import_clean(temp_file("empty.obj", "")); }) == "/tmp/girtd_frontend_test_empty.obj: empty file");
  // The line of the face (4) or vertex (2) at fault, found by the pre-scan.
  CHECK(error_of([] { import_clean(temp_file("idx.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")); }) ==
        "/tmp/girtd_frontend_test_idx.obj:4: vertex index 9 is out of range (the file has 3 vertices)");
  CHECK(error_of([] { import_clean(temp_file("neg.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n")); }) ==
        "/tmp/girtd_frontend_test_neg.obj:3: vertex index -3 is out of range (2 vertices so far)");
  CHECK(error_of([] { import_clean(temp_file("idx.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n")); }) ==
        "/tmp/girtd_frontend_test_idx.off:6: vertex index 5 is out of range (the file has 3 vertices, counted from 0)");
  CHECK(error_of([] { import_clean(temp_file("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_nan.obj:2: vertex 2 has a coordinate that is NaN or infinite");
  CHECK(error_of([] { import_clean(temp_file("inf.off", "OFF\n3 1 0\n0 0 0\n1 0 -1e999\n0 1 0\n3 0 1 2\n")); }) ==
        "/tmp/girtd_frontend_test_inf.off:4: vertex 1 has a coordinate that is NaN or infinite");
  // assimp's OFF reader drops faces of more than 9 corners: refused, with the line.
  CHECK(error_of([] { import_clean(temp_file("ten.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n10 0 1 2 0 1 2 0 1 2 0\n")); })
            .rfind("/tmp/girtd_frontend_test_ten.off:6: a face of 10 corners", 0) == 0);
  // A count far beyond what the file could hold is refused before assimp allocates for it.
  CHECK(error_of([] { import_clean(temp_file("huge.off", "OFF\n99999999999 1 0\n0 0 0\n")); }) ==
        "/tmp/girtd_frontend_test_huge.off:2: header claims 99999999999 vertices, more than the file's 26 bytes could hold");
}

namespace {

// A binary PLY: 4 vertices (unit square in z = 0) and the faces given as
// (count, indices...) lists with a uint count and int indices.
std::string binary_ply(bool big_endian, const std::vector<std::vector<uint32_t>>& faces) {
  std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                    std::to_string(faces.size()) + "\nproperty list uint int vertex_indices\nend_header\n";
  auto put32 = [&](uint32_t v) {
    for (int k = 0; k < 4; ++k) out += static_cast<char>(big_endian ? v >> (24 - 8 * k) : v >> (8 * k));
  };
  const uint32_t one = 0x3f800000;  // 1.0f
  for (uint32_t xy : {0u, 1u, 3u, 2u}) {
    put32(xy & 1 ? one : 0);
    put32(xy & 2 ? one : 0);
    put32(0);
  }
  for (const std::vector<uint32_t>& f : faces)
    for (uint32_t v : f) put32(v);
  return out;
}

}  // namespace

TEST_CASE("model import: every format assimp reads, by extension", "[frontend]") {
  for (const char* f : {"a/b/model.OBJ", "m.ply", "m.stl", "m.off", "m.3ds", "m.fbx", "m.gltf", "m.glb", "m.dae", "m.x"})
    CHECK(is_model_file(f));
  for (const char* f : {"scene.trace", "frame.dda", "noextension", "m.png", "thesis.raw"}) CHECK_FALSE(is_model_file(f));
  // Not a 3DS file: assimp's refusal, in the child, as the file's one line.
  CHECK(error_of([] { import_clean(temp_file("m.3ds", "xyz")); }).rfind("/tmp/girtd_frontend_test_m.3ds: cannot read the model: ", 0) == 0);
}

TEST_CASE("model import: PLY list lengths are checked before assimp allocates for them", "[frontend]") {
  // Valid binary files in both byte orders: a quad and a triangle.
  for (bool big : {false, true}) {
    const std::string path = temp_file(big ? "be.ply" : "le.ply", binary_ply(big, {{4, 0, 1, 2, 3}, {3, 0, 1, 2}}));
    const Mesh m = import_clean(path);
    CHECK(m.positions.size() == 4);
    REQUIRE(m.polygon_count() == 2);
    CHECK(m.polygon(0).size == 4);
  }
  // 10^8 indices claimed in a 200-byte file (assimp took 800 MB for it).
  CHECK(error_of([] { import_clean(temp_file("huge.ply", binary_ply(false, {{100000000, 0, 1, 2}}))); }) ==
        "/tmp/girtd_frontend_test_huge.ply:@216: element 'face' 0 lists 100000000 values (limit 65536)");
  // Within the limit but more than the bytes left: 1000 x 4 bytes, 12 left.
  CHECK(error_of([] { import_clean(temp_file("short.ply", binary_ply(false, {{1000, 0, 1, 2}}))); }) ==
        "/tmp/girtd_frontend_test_short.ply:@216: element 'face' 0 lists 1000 values: 4000 bytes, but 12 are left");
  CHECK(error_of([] { import_clean(temp_file("bidx.ply", binary_ply(true, {{3, 0, 1, 4}}))); }) ==
        // big-endian header 165 bytes + 4 x 12 vertex bytes + the count + two indices = byte 225
        "/tmp/girtd_frontend_test_bidx.ply:@225: element 'face' 0: vertex index 4 is out of range (the file has 4 vertices, "
        "counted from 0)");
  // ASCII: the line of the instance.
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  CHECK(error_of([&] { import_clean(temp_file("long.ply", head + "4000000000 0 1 2\n")); }) ==
        "/tmp/girtd_frontend_test_long.ply:13: element 'face' 0 lists 4000000000 values (limit 65536)");
  CHECK(error_of([&] { import_clean(temp_file("few.ply", head + "5 0 1 2\n")); }) ==
        "/tmp/girtd_frontend_test_few.ply:13: element 'face' 0 claims 5 values but its line has 3");
  CHECK(error_of([&] { import_clean(temp_file("ok.ply", head + "3 0 1 2\n")); }) == "");  // the head itself is fine
  // assimp 5.2.5 would read a blank or comment line among the elements as an element.
  CHECK(error_of([&] { import_clean(temp_file("blank.ply", head + "\n3 0 1 2\n")); }) ==
        "/tmp/girtd_frontend_test_blank.ply:13: a blank or comment line among the elements (assimp 5.2.5 would read it "
        "as one)");
  CHECK(error_of([&] {
          import_clean(temp_file("nanv.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                             "property float z\nend_header\n0 0 0\n1 inf 0\n0 1 0\n"));
        }) == "/tmp/girtd_frontend_test_nanv.ply:9: vertex 1 has a coordinate that is NaN or infinite");
}

TEST_CASE("scene: a broken model is the scene's error, at the line naming it", "[frontend]") {
  temp_file("bad_model.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  const std::string scene = temp_file("badmodel.json", "{\"girtd_scene\": 1,\n \"models\": [\n  {\"name\": \"a\",\n   \"file\": \"girtd_frontend_test_bad_model.obj\"}]}\n");
  CHECK(error_of([&] { read_scene(scene, Params::defaults()); }) ==
        scene + ":4: model /tmp/girtd_frontend_test_bad_model.obj:4: vertex index 9 is out of range (the file has 3 vertices)");
}

TEST_CASE("scene: JSON nested deeper than 64 levels is refused before parsing", "[frontend]") {
  // 400 KB of '[' crashed the line scanner (one recursion per level).
  const std::string deep = temp_file("deep.json", std::string(400000, '['));
  CHECK(error_of([&] { read_scene(deep, Params::defaults()); }) == deep + ":1: JSON nested deeper than 64 levels");
  // The 65th level, on line 3 (brackets inside strings do not count).
  const std::string text = "{\"girtd_scene\": 1, \"comment\": \"[[[[\",\n \"models\": [],\n \"frames\": " +
                           std::string(63, '[') + std::string(63, ']') + "}";
  const std::string ok = temp_file("deep64.json", text);
  CHECK(error_of([&] { read_scene(ok, Params::defaults()); }) == ok + ":2: \"models\" must be a non-empty list");
  const std::string too = temp_file("deep65.json", "{\"comment\": \"[[[[\",\n\n " + std::string(64, '[') + "}");
  CHECK(error_of([&] { read_scene(too, Params::defaults()); }) == too + ":3: JSON nested deeper than 64 levels");
}

TEST_CASE("JSON lines: pointers with escaped names, array elements, nearest ancestor", "[frontend]") {
  const JsonLines lines("{\n \"a/b\": {\n  \"x~y\": [1,\n   2, {\"k\\u0041\": 3}]},\n \"z\": 0}\n");
  CHECK(lines.line("") == 1);
  CHECK(lines.line("/a~1b") == 2);
  CHECK(lines.line("/a~1b/x~0y") == 3);
  CHECK(lines.line("/a~1b/x~0y/0") == 3);
  CHECK(lines.line("/a~1b/x~0y/1") == 4);
  CHECK(lines.line("/a~1b/x~0y/2/kA") == 4);  // a key with an escape, decoded
  CHECK(lines.line("/a~1b/x~0y/7") == 3);     // no element 7: its array's line
  CHECK(lines.line("/z") == 5);
  CHECK(lines.line("/missing/deeper") == 1);
}

TEST_CASE("scene: names with / and ~ are plain names", "[frontend]") {
  const std::string scene = temp_file("names.json", R"({"girtd_scene": 1,
  "camera": {"eye": [0, 0, 8], "target": [0, 0, 0]},
  "materials": {"a/b": {"colour": [255, 0, 0]}, "c~1": {"colour": [0, 255, 0], "n": 7}},
  "models": [{"name": "m/1", "file": ")" + kModels + R"(cube.obj", "material": "a/b"},
             {"name": "m~0", "file": ")" + kModels + R"(cube.obj", "material": "c~1"}],
  "frames": [{}, {"models": {"m/1": {"translate": [1, 0, 0]}, "m~0": {"translate": [0, 2, 0]}}}]
})");
  const Trace t = read_scene(scene, Params::defaults());
  REQUIRE(t.frames.size() == 2);
  const WorldFrame& w = t.frames[1].world;
  REQUIRE(w.surfaces.size() == 12);
  CHECK(w.surfaces[0].r == 255);
  CHECK(w.surfaces[6].g == 255);
  CHECK(w.surfaces[6].n == 7);
  double max_x = -1e9, max_y = -1e9;
  for (size_t i = 0; i < 6; ++i)
    for (const Vec3& v : w.polygons[i].p) max_x = std::max(max_x, v.x);
  for (size_t i = 6; i < 12; ++i)
    for (const Vec3& v : w.polygons[i].p) max_y = std::max(max_y, v.y);
  CHECK(max_x == Approx(2));  // cube.obj spans -1..1
  CHECK(max_y == Approx(3));
  // An error under such a name finds its line.
  const std::string bad = temp_file("badname.json", "{\"girtd_scene\": 1,\n \"materials\": {\"a/b\":\n  {\"n\": 201}}}\n");
  CHECK(error_of([&] { read_scene(bad, Params::defaults()); }) == bad + ":3: \"materials/a/b/n\" = 201 is outside 1..200");
}

TEST_CASE("scene: a frame's polygon corners are capped before anything is placed", "[frontend]") {
  // A 100 x 100 grid of quads: 40,000 corners; 751 of them in a frame place 30,040,000 > 30,000,000.
  std::ostringstream grid;
  for (int j = 0; j <= 100; ++j)
    for (int i = 0; i <= 100; ++i) grid << "v " << i << " " << j << " 0\n";
  for (int j = 0; j < 100; ++j)
    for (int i = 0; i < 100; ++i) {
      const int a = j * 101 + i + 1;
      grid << "f " << a << " " << a + 1 << " " << a + 102 << " " << a + 101 << "\n";
    }
  temp_file("grid.obj", grid.str());
  std::string models;
  for (int m = 0; m < 751; ++m)
    models += std::string(m ? ", " : "") + "{\"name\": \"g" + std::to_string(m) + "\", \"file\": \"girtd_frontend_test_grid.obj\"}";
  const std::string scene =
      temp_file("frames.json", "{\"girtd_scene\": 1,\n \"models\": [" + models + "],\n \"frames\": [{}, {}]}\n");
  CHECK(error_of([&] { read_scene(scene, Params::defaults()); }) ==
        scene + ":2: 30040000 polygon corners in a frame is more than the 30000000 a scene may place: use smaller models "
                "or fewer of them");
  // Frames are placed one at a time: 100,000 frames of the grid are taken (the cap is the frame's, not the scene's).
  std::string frames;
  for (int f = 0; f < 100000; ++f) frames += f ? ", {}" : "{}";
  const std::string long_scene = temp_file(
      "long.json", "{\"girtd_scene\": 1,\n \"models\": [{\"file\": \"girtd_frontend_test_grid.obj\"}],\n \"frames\": [" +
                       frames + "]}\n");
  FrameSource source = open_scene(long_scene, Params::defaults());
  CHECK(source.frames() == 100000);
  CHECK(source.items() == 100000);  // an object a frame
  CHECK(source.take(0).world.polygons.size() == 10000);
  CHECK(source.take(1).world.polygons.size() == 10000);
}

TEST_CASE("scene: models, materials, camera and frames, unknown keys fail with their line", "[frontend]") {
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
  CHECK(error_of([&] { read_scene(bad, Params::defaults()); }) ==
        bad + ":5: unknown key \"colour\" in \"models/0\" (known: crease_deg, file, material, mesh, name, rotate_deg, scale, "
              "translate)");
  const std::string syntax = temp_file("syntax.json", "{\n  \"girtd_scene\": 1,\n  \"q\": ,\n}\n");
  CHECK(error_of([&] { read_scene(syntax, Params::defaults()); }).rfind(syntax + ":3: invalid JSON", 0) == 0);
  const std::string range = temp_file("range.json", "{\"girtd_scene\": 1,\n\"materials\": {\"m\": {\"cre\": [0, 0, 0, 0, 0, 0, 2]}},\n\"models\": []}\n");
  CHECK(error_of([&] { read_scene(range, Params::defaults()); }) == range + ":2: \"materials/m/cre/6\" = 2 is outside 0..1");
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
