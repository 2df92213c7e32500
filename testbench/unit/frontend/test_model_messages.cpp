// Model files that assimp reads with something to say: each class of
// sim/io/README.md's table with a small file of ours. A warning leaves the
// polygons exactly as the file has them; an error refuses the model.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "input_test_support.hpp"
#include "io/assimp_messages.hpp"
#include "io/scene_reader.hpp"

using namespace girtd;
using namespace girtd::test;

namespace {

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\n";

struct Imported {
  Mesh mesh;
  std::vector<std::string> warnings;
};

Imported import(const std::string& path) {
  Imported m;
  m.mesh = import_model(path, m.warnings).mesh;
  return m;
}

}  // namespace

TEST_CASE("model messages: a missing material library is one warning, and the model is drawn", "[frontend]") {
  const std::string path = temp_file("nomtl.obj", "mtllib gone.mtl\n" + kTriangle +
                                                      "usemtl red\nf 1 2 3\nusemtl blue\nf 2 4 3\n");
  const Imported m = import(path);
  CHECK(m.mesh.polygon_count() == 2);
  REQUIRE(m.warnings.size() == 1);  // not one per usemtl
  CHECK(m.warnings[0].rfind(path + ":1: material library 'gone.mtl' not found", 0) == 0);
}

TEST_CASE("model messages: usemtl of an unknown name is a warning once per name", "[frontend]") {
  temp_file("lib.mtl", "newmtl red\nKd 1 0 0\n");
  const std::string path = temp_file("usemtl.obj", "mtllib girtd_frontend_test_lib.mtl\n" + kTriangle +
                                                       "usemtl red\nf 1 2 3\nusemtl nosuch\nf 2 4 3\nusemtl nosuch\n"
                                                       "f 1 4 3\n");
  const Imported m = import(path);
  CHECK(m.mesh.polygon_count() == 3);
  REQUIRE(m.warnings.size() == 1);
  CHECK(m.warnings[0].rfind(path + ":8: usemtl 'nosuch' names no material", 0) == 0);
}

TEST_CASE("model messages: a broken material library does not stop the model (default material, warned)", "[frontend]") {
  temp_file("broken.mtl", "newmtl m\nKd x y z\n");  // assimp 5.2.5 fails the whole import on the bad number
  const std::string path = temp_file("brokenmtl.obj", "mtllib girtd_frontend_test_broken.mtl\n" + kTriangle +
                                                          "usemtl m\nf 1 2 3\n");
  const Imported m = import(path);
  CHECK(m.mesh.polygon_count() == 1);
  REQUIRE(m.warnings.size() == 1);
  CHECK(m.warnings[0].rfind(path + ": the files it names (its material library) could not be read", 0) == 0);
}

TEST_CASE("model messages: an empty face is a warning (assimp's Err), the rest is drawn", "[frontend]") {
  const std::string path = temp_file("emptyface.obj", kTriangle + "f\nf 1 2 3\n");
  const Imported m = import(path);
  CHECK(m.mesh.polygon_count() == 1);
  CHECK(m.warnings == std::vector<std::string>{path + ": Obj: Ignoring empty face"});
}

TEST_CASE("model messages: what assimp drops from a facet is refused with the facet's line", "[frontend]") {
  // STL: assimp 5.2.5 drops a fourth vertex in a facet (with an Err).
  const std::string stl = temp_file("quad.stl", "solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                                "vertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid q\n");
  CHECK(error_of([&] { import(stl); }) == stl + ":2: a facet of 4 vertices, not 3");
}

TEST_CASE("model messages: an ASCII STL is read as assimp reads it, and refused where its reader would throw",
          "[frontend]") {
  const std::string facet = "outer loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  // assimp reads `facet` and `normal` across a line end, and the numbers on
  // normal's line: a triangle.
  CHECK(import(temp_file("split.stl", "solid s\nfacet\nnormal 0 0 1\n" + facet + "endsolid s\n")).mesh.polygon_count() ==
        1);
  // A facet without `normal` gets no normal from assimp: its normal and
  // position counts differ, and it throws at the solid's end.
  const std::string no_normal = temp_file("nonormal.stl", "solid s\nfacet norm 0 0 1\n" + facet + "endsolid s\n");
  CHECK(error_of([&] { import(no_normal); }) ==
        no_normal + ":2: 'facet' without 'normal' after it (assimp 5.2.5 would read no normal for it)");
  // assimp skips blanks, not line ends, before each number.
  const std::string short_normal = temp_file("shortnormal.stl", "solid s\nfacet normal 0 0\n1\n" + facet + "endsolid\n");
  CHECK(error_of([&] { import(short_normal); }) == short_normal + ":2: 'facet normal' with fewer than 3 numbers on its line");
  // assimp starts a solid as if a facet had just ended: a vertex there is dropped.
  const std::string stray = temp_file("stray.stl", "solid s\nvertex 0 0 0\nfacet normal 0 0 1\n" + facet + "endsolid\n");
  CHECK(error_of([&] { import(stray); }) == stray + ":2: a 'vertex' before any 'facet normal'");
  // Every solid is read: the second one's facet of 2 vertices.
  const std::string second = temp_file("second.stl", "solid a\nfacet normal 0 0 1\n" + facet + "endsolid a\nsolid b\n" +
                                                         "facet normal 0 0 1\nvertex 0 0 0\nvertex 1 0 0\nendsolid b\n");
  CHECK(error_of([&] { import(second); }) == second + ":11: a facet of 2 vertices, not 3");
}

TEST_CASE("model messages: an STL assimp would convert, or read only in part, is refused", "[frontend]") {
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  // assimp strips a UTF-8 byte-order mark before it tells binary from ASCII.
  const std::string bom = temp_file("bom.stl", "\xEF\xBB\xBFsolid s\n" + facet + "endsolid s\n");
  CHECK(error_of([&] { import(bom); }) ==
        bom + ":1: the file starts with a byte-order mark (assimp 5.2.5 converts the whole file, a binary one too, from it)");
  // After `endsolid`, assimp reads on only into another `solid`.
  const std::string after = temp_file("after.stl", "solid s\n" + facet + "endsolid s\n" + facet);
  CHECK(error_of([&] { import(after); }) ==
        after + ":10: text after 'endsolid' that is not another 'solid' (assimp 5.2.5 drops it)");
  // An ASCII file whose bytes 80-83 ("8333" inside a name) make 84 + 50 n wrap
  // to its size in assimp's 32 bits: assimp reads it as binary.
  std::string wrapped = "solid " + std::string(74, 'x') + "8333 y\n" + facet + "endsolid\n";
  wrapped += std::string(324 - wrapped.size() - 1, ' ') + "\n";
  REQUIRE(wrapped.size() == 324);  // 84 + 50 x 858993464 = 324 (mod 2^32)
  const std::string wrap = temp_file("wrap.stl", wrapped);
  CHECK(error_of([&] { import(wrap); }) == wrap + ":@80: binary STL claims 858993464 triangles (42949673284 bytes) but "
                                                  "the file has 324 bytes");
}

TEST_CASE("model messages: a PLY header gives its format once", "[frontend]") {
  const std::string path = temp_file("twoformats.ply", "ply\nformat ascii 1.0\ncomment x\nformat binary_little_endian 1.0\n"
                                                       "element vertex 0\nend_header\n");
  CHECK(error_of([&] { import(path); }) == path + ":4: a second 'format' line (the format is given once, on line 2)");
}

TEST_CASE("model messages: what assimp 5.2.5 would misread without a word is refused with its line", "[frontend]") {
  CHECK(error_of([] { import(temp_file("bom.obj", "\xEF\xBB\xBF" + kTriangle + "f 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_bom.obj:1: the file starts with a UTF-8 byte-order mark (assimp 5.2.5 would lose its "
        "first statement)");
  CHECK(error_of([] { import(temp_file("indent.obj", "v 0 0 0\n  v 1 0 0\nv 0 1 0\nf 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_indent.obj:2: an indented 'v' (assimp 5.2.5 skips it): remove the leading white space");
  // Line ends assimp knows and this reader does not: the vertex after the CR would be lost.
  CHECK(error_of([] { import(temp_file("cr.obj", "# c\rv 5 5 5\n" + kTriangle + "f 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_cr.obj:1: a NUL, a form feed, a vertical tab or a CR without LF: assimp 5.2.5 reads "
        "lines and blanks there otherwise");
  CHECK(error_of([] { import(temp_file("word.obj", "v 9 9 x\n" + kTriangle + "f 2 3 4\n")); }) ==
        "/tmp/girtd_frontend_test_word.obj:1: 'x' is not a number assimp 5.2.5 reads (it would drop the vertex)");
  CHECK(error_of([] { import(temp_file("big.obj", kTriangle + "f 1 2 3 9900000000000000001\n")); }) ==
        "/tmp/girtd_frontend_test_big.obj:5: corner '9900000000000000001': an index assimp 5.2.5 misreads (write a plain "
        "non-zero integer: no leading '0' or '+', at most 2147483647)");
  CHECK(error_of([] { import(temp_file("comment.obj", kTriangle + "f 1 2 3\n# second \\\nf 2 4 3\n")); }) ==
        "/tmp/girtd_frontend_test_comment.obj:6: a '\\' at the end of a comment or a '' line: assimp 5.2.5 would join "
        "the next line to it and lose that statement");
  // assimp switches on the first character: "lod 1" is a line through vertex 1, "fx ..." a face.
  CHECK(error_of([] { import(temp_file("lod.obj", kTriangle + "f 1 2 3\nlod 1\n")); }) ==
        "/tmp/girtd_frontend_test_lod.obj:6: 'lod' starts with 'l': assimp 5.2.5 reads it as a line");
  // ... and skips everything between cstype and end, vertices included.
  CHECK(error_of([] { import(temp_file("cstype.obj", "cstype bspline\nv 0 0 0\nend\n" + kTriangle + "f 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_cstype.obj:2: a 'v' inside a cstype ... end block (assimp 5.2.5 skips the whole "
        "block)");
  // Numbers as assimp's fast_atof reads them: no hexadecimal, at most 15 decimals, within a float.
  CHECK(error_of([] { import(temp_file("hex.obj", "v 0 0 0\nv 2 0 0\nv 0x1 1 0\nf 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_hex.obj:3: '0x1' is not a decimal number (assimp 5.2.5 would misread it)");
  // A comment after a vertex: assimp counts its numbers too ("# 1 2" makes 5: the vertex is dropped).
  CHECK(error_of([] { import(temp_file("vcomment.obj", "v 0 0 0 # 1 2\n" + kTriangle + "f 2 3 4\n")); }) ==
        "/tmp/girtd_frontend_test_vcomment.obj:1: a comment after 'v' (assimp 5.2.5 counts its numbers too): put it on a "
        "line of its own");
  // An mtllib naming the model: assimp's MTL reader would run on the OBJ text (and can crash).
  CHECK(error_of([] { import(temp_file("self.obj", "mtllib girtd_frontend_test_self.obj\n" + kTriangle + "f 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_self.obj:1: mtllib names the model file itself");
  // OFF indices are digits only: assimp reads "+3" as 0.
  CHECK(error_of([] { import(temp_file("plus.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 2 +3\n")); }) ==
        "/tmp/girtd_frontend_test_plus.off:7: vertex index +3 is out of range (the file has 4 vertices, counted from 0)");
  // PLY: a second face element overruns assimp's arrays; a sign on an unsigned value slides the line.
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty uchar flag\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\n";
  CHECK(error_of([&] {
          import(temp_file("faces2.ply", ply + "element face 1\nproperty list uchar int vertex_indices\nend_header\n"));
        }) == "/tmp/girtd_frontend_test_faces2.ply:10: a second 'face' element (assimp 5.2.5 overruns its arrays on it)");
  CHECK(error_of([&] {
          import(temp_file("sign.ply", ply + "end_header\n0 0 0 0\n-1 1 0 0\n0 0 1 0\n3 0 1 2\n"));
        }) == "/tmp/girtd_frontend_test_sign.ply:12: element 'vertex' 1: '-1' is not an integer of its type (property flag)");
  // OFF: a comment line among the faces is read as a face of 0 corners, and the last face is lost.
  CHECK(error_of([] {
          import(temp_file("comment.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n# faces\n3 0 1 2\n3 1 3 2\n"));
        }) == "/tmp/girtd_frontend_test_comment.off:7: a blank or comment line inside the vertex and face lists (assimp "
              "5.2.5 reads it as a face)");
  // OFF: no edge count, so assimp takes the integer part of the first coordinate for it.
  CHECK(error_of([] { import(temp_file("edges.off", "OFF\n3 1\n1.5 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")); }) ==
        "/tmp/girtd_frontend_test_edges.off:3: OFF edge count '1.5' is not a non-negative integer (the header is "
        "vertices faces edges)");
  CHECK(error_of([] { import(temp_file("v5.obj", "v 0 0 0 1 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_v5.obj:1: a vertex of 5 numbers (assimp 5.2.5 reads x y z, x y z w or x y z r g b)");
  CHECK(error_of([] { import(temp_file("dot.obj", "v .5 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_dot.obj:1: '.5' is not a number assimp 5.2.5 reads (it would drop the vertex): write "
        "0.5");
  CHECK(error_of([] { import(temp_file("zero.obj", kTriangle + "f 01 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_zero.obj:5: corner '01': an index assimp 5.2.5 misreads (write a plain non-zero "
        "integer: no leading '0' or '+', at most 2147483647)");
  CHECK(error_of([] { import(temp_file("cont.obj", kTriangle + "f 1 2 \\\n\nf 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_cont.obj:6: a '\\' continuation runs into an empty line or another '\\' (assimp 5.2.5 "
        "would lose what follows)");
  CHECK(error_of([] {
          import(temp_file("strips.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                         "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
                                         "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
        }) == "/tmp/girtd_frontend_test_strips.ply:7: triangle strips ('element tristrips') are not read: write faces "
              "instead");
}

TEST_CASE("model messages: a continuation joins lines as assimp does", "[frontend]") {
  // "f 1 2 \" + "3": the face 1 2 3, the same polygons as the joined file.
  const Imported m = import(temp_file("joined.obj", kTriangle + "f 1 2 \\\n3\nf 2 \\\n 4 3\n"));
  CHECK(m.mesh.polygon_count() == 2);
  CHECK(m.warnings.empty());
  // "f 1\" + "2 3 4": assimp reads "f 12 3 4", a triangle, where the writer likely meant a quad.
  std::string twelve;
  for (int i = 0; i < 12; ++i) twelve += "v " + std::to_string(i % 3) + " " + std::to_string(i / 3) + " 0\n";
  CHECK(error_of([&] { import(temp_file("glued.obj", twelve + "f 1\\\n2 3 4\n")); }) ==
        "/tmp/girtd_frontend_test_glued.obj:13: a '\\' continuation with no space on either side: assimp 5.2.5 joins "
        "'1' and '2' into one number");
}

TEST_CASE("model messages: a binary PLY whose first data byte is a line feed is refused at that byte", "[frontend]") {
  // assimp 5.2.5 drops that byte (PlyParser) and reads every value after it shifted.
  const std::string head =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  std::string body;
  auto put = [&](uint32_t v, int bytes) {
    for (int k = 0; k < bytes; ++k) body += static_cast<char>(v >> (8 * k));
  };
  for (uint32_t bits : {0x3F80000Au, 0u, 0u, 0u, 0x3F800000u, 0u, 0u, 0u, 0x3F800000u}) put(bits, 4);  // x = 1.0000012
  put(3, 1);
  for (uint32_t i : {0u, 1u, 2u}) put(i, 4);
  const std::string path = temp_file("newline.ply", head + body);
  CHECK(error_of([&] { import(path); }) ==
        path + ":@" + std::to_string(head.size()) +
            ": the first data byte is 0x0A, which assimp 5.2.5 drops (every value after it would be read shifted): end "
            "the header's lines with CR LF to keep it");
}

TEST_CASE("model messages: a NaN in a binary file is refused at its byte", "[frontend]") {
  std::string stl(80, ' ');
  auto put = [&](uint32_t v) {
    for (int k = 0; k < 4; ++k) stl += static_cast<char>(v >> (8 * k));
  };
  put(1);                                                 // one triangle
  for (uint32_t bits : {0u, 0u, 0x3F800000u}) put(bits);  // normal
  for (uint32_t bits : {0u, 0u, 0u, 0x3F800000u, 0u, 0u, 0u, 0x7FC00000u, 0u}) put(bits);  // corner 2's y is NaN
  stl += std::string(2, '\0');
  const std::string path = temp_file("nan.stl", stl);
  // 84 header bytes + 12 normal bytes + corner 2's y (2 x 12 + 4) = byte 124
  CHECK(error_of([&] { import(path); }) == path + ":@124: triangle 0 corner 2 has a coordinate that is NaN or infinite");
}

TEST_CASE("model messages: the sorting table", "[frontend]") {
  CHECK(classify_assimp_message("OBJ: Unable to locate material file a.mtl", true) == AssimpMessage::kIgnored);
  CHECK(classify_assimp_message("OBJ: failed to locate material red, creating new material", true) ==
        AssimpMessage::kIgnored);
  CHECK(classify_assimp_message("Obj: Ignoring empty face", true) == AssimpMessage::kWarning);
  CHECK(classify_assimp_message("OFF: Vertex index is out of range", true) == AssimpMessage::kError);
  CHECK(classify_assimp_message("something new in a later assimp", true) == AssimpMessage::kError);
  CHECK(classify_assimp_message("Unable to parse property instance. Skipping this element instance", false) ==
        AssimpMessage::kError);
  CHECK(classify_assimp_message("Validation warning: There are unreferenced vertices", false) ==
        AssimpMessage::kIgnored);
  CHECK(classify_assimp_message("STL: unexpected EOF. 'endsolid' keyword was expected", false) ==
        AssimpMessage::kWarning);
  CHECK(strip_assimp_prefix("Warn,  T0: OBJ: x \n") == "OBJ: x");
  CHECK(strip_assimp_prefix("Error, T0: OFF: y") == "OFF: y");
}

TEST_CASE("model messages: a scene passes on its models' warnings, once per model file", "[frontend]") {
  const std::string obj = temp_file("scene_nomtl.obj", "mtllib gone.mtl\n" + kTriangle + "f 1 2 3\n");
  const std::string scene = temp_file(
      "warn_scene.json", R"({"girtd_scene": 1, "models": [{"name": "a", "file": "girtd_frontend_test_scene_nomtl.obj"},
                                               {"name": "b", "file": "girtd_frontend_test_scene_nomtl.obj"}]})");
  const Trace t = read_scene(scene, Params::defaults());
  REQUIRE(t.warnings.size() == 1);
  CHECK(t.warnings[0].rfind(obj + ":1: material library 'gone.mtl' not found", 0) == 0);
}

TEST_CASE("model messages: a round-trip double is read, digits assimp drops are refused only where they count", "[frontend]") {
  // An exporter's doubles: assimp drops the digits past the 15th, and the float it reads is the same.
  const Imported m = import(temp_file("roundtrip.obj", "v 0.0009999999983333334 0 0\nv 1.0000000000000000001 0 0\n"
                                                       "v 0 0.99999999999999999 0\nf 1 2 3\n"));
  CHECK(m.mesh.polygon_count() == 1);
  CHECK(m.warnings.empty());
  CHECK(std::abs(m.mesh.positions[0].x - 0.0009999999983333334) < 3e-10);  // a float's step there: 1.2e-10
  // Just past the midpoint between 1 and the next float: without its last digits, below it (1.0).
  CHECK(error_of([] { import(temp_file("step.obj", "v 1.0000000596046449 0 0\nv 0 0 0\nv 0 1 0\nf 1 2 3\n")); }).find(
            "'1.0000000596046449' has more than 15 digits after the point") != std::string::npos);
  // 1.2e-16 in fixed notation: past the 15th digit is all there is.
  CHECK(error_of([] { import(temp_file("tiny.obj", "v 0.00000000000000012 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_tiny.obj:1: '0.00000000000000012' has more than 15 digits after the point; assimp "
        "5.2.5 drops the rest and would read 0.000000000000000 (assimp 5.2.5 would misread it)");
  // Exponents: assimp scales by powf(10, e), where 10^39 is already infinite.
  CHECK(import(temp_file("exp.obj", "v 1e-005 0 0\nv 1.5E+2 0 0\nv 0 2.e1 0\nf 1 2 3\n")).mesh.polygon_count() == 1);
  CHECK(error_of([] { import(temp_file("zeroexp.obj", "v 0e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); }) ==
        "/tmp/girtd_frontend_test_zeroexp.obj:1: '0e39' is read as NaN (assimp 5.2.5 applies the exponent as a float "
        "power of 10) (assimp 5.2.5 would misread it)");
  CHECK(error_of([] { import(temp_file("bigexp.obj", "v 0.001e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); }).find(
            "'0.001e39' is read as infinity") != std::string::npos);
  CHECK(error_of([] { import(temp_file("longexp.obj", "v 1e-99999999999999999999 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")); })
            .find("has an exponent of more than 9 digits") != std::string::npos);
}

namespace {

// A glTF 2.0 triangle: three float VEC3 positions (36 bytes, embedded), one
// accessor per line from line 7 on, `accessor` the position accessor's text.
std::string gltf_triangle(const std::string& accessor, const std::string& more_accessors = "") {
  return "{\"asset\": {\"version\": \"2.0\"},\n"
         "\"scenes\": [{\"nodes\": [0]}], \"nodes\": [{\"mesh\": 0}],\n"
         "\"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}}]}],\n"
         "\"buffers\": [{\"byteLength\": 36, \"uri\": \"data:application/octet-stream;base64,"
         "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}],\n"
         "\"bufferViews\": [{\"buffer\": 0, \"byteLength\": 36}],\n"
         "\"accessors\": [" + accessor + more_accessors + "\n]}\n";
}

// The same document as a binary glTF: a 12-byte header and one JSON chunk
// (its length padded to 4 with blanks, as the format asks).
std::string glb_of(std::string json) {
  while (json.size() % 4) json += ' ';
  auto u32 = [](uint32_t v) { return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; };
  return "glTF" + u32(2) + u32(static_cast<uint32_t>(20 + json.size())) + u32(static_cast<uint32_t>(json.size())) +
         "JSON" + json;
}

}  // namespace

TEST_CASE("model messages: a glTF accessor within its buffer view is read, one past it is refused", "[frontend]") {
  const std::string positions = "\n{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\", "
                                "\"min\": [0, 0, 0], \"max\": [1, 1, 0]}";
  CHECK(import(temp_file("tri.gltf", gltf_triangle(positions))).mesh.polygon_count() == 1);
  // An offset of 4: the 3 x 12 bytes end at byte 40 of the 36-byte view (assimp
  // 5.2.5 bounds the read by the view's length alone and reads 4 bytes past it).
  const std::string shifted = "\n{\"bufferView\": 0, \"byteOffset\": 4, \"componentType\": 5126, \"count\": 3, "
                              "\"type\": \"VEC3\", \"min\": [0, 0, 0], \"max\": [1, 1, 0]}";
  const std::string past = temp_file("past.gltf", gltf_triangle(shifted));
  CHECK(error_of([&] { import(past); }) ==
        past + ":7: accessor 0: its elements run past its buffer view of 36 bytes (offset 4, 3 x 12 bytes apart; "
               "assimp 5.2.5 would read past it)");
  // The same in a .glb: its JSON chunk's line.
  const std::string glb = temp_file("past.glb", glb_of(gltf_triangle(shifted)));
  CHECK(error_of([&] { import(glb); }) ==
        glb + ": accessor 0 (line 7 of the JSON chunk): its elements run past its buffer view of 36 bytes (offset 4, "
              "3 x 12 bytes apart; assimp 5.2.5 would read past it)");
  // A stride: 3 elements 16 bytes apart need 2 x 16 + 12 = 44 bytes.
  std::string strided = gltf_triangle(positions);
  strided.replace(strided.find("\"byteLength\": 36}]"), 18, "\"byteLength\": 36, \"byteStride\": 16}]");
  const std::string stride = temp_file("stride.gltf", strided);
  CHECK(error_of([&] { import(stride); }) ==
        stride + ":7: accessor 0: its elements run past its buffer view of 36 bytes (offset 0, 3 x 16 bytes apart; "
                 "assimp 5.2.5 would read past it)");
}

TEST_CASE("model messages: a glTF buffer view past its buffer, or an unknown type, is refused with its line", "[frontend]") {
  const std::string positions = "\n{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\"}";
  std::string longer = gltf_triangle(positions);
  longer.replace(longer.find("\"byteLength\": 36}]"), 18, "\"byteOffset\": 8, \"byteLength\": 36}]");
  const std::string view = temp_file("view.gltf", longer);
  CHECK(error_of([&] { import(view); }) ==
        view + ":5: buffer view 0: bytes 8 to 44 of buffer 0 of 36 bytes (a view lies within its buffer; "
               "assimp 5.2.5's glTF 1 reader reads past it)");
  const std::string vec6 = temp_file("vec6.gltf", gltf_triangle(positions, ",\n{\"bufferView\": 0, \"componentType\": "
                                                                           "5126, \"count\": 1, \"type\": \"VEC6\"}"));
  CHECK(error_of([&] { import(vec6); }) == vec6 + ":8: accessor 1: type \"VEC6\" is not a glTF accessor type");
  const std::string code = temp_file("code.gltf", gltf_triangle(positions, ",\n{\"bufferView\": 0, \"componentType\": "
                                                                           "5127, \"count\": 1, \"type\": \"VEC3\"}"));
  CHECK(error_of([&] { import(code); }) == code + ":8: accessor 1: componentType 5127 is not a glTF component type");
  // Sparse values: 2 replaced VEC3s (24 bytes) from byte 24 of the 36-byte view.
  const std::string sparse = temp_file(
      "sparse.gltf", gltf_triangle(positions, ",\n{\"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\", \"sparse\": "
                                              "{\"count\": 2, \"indices\": {\"bufferView\": 0, \"componentType\": 5125}, "
                                              "\"values\": {\"bufferView\": 0, \"byteOffset\": 24}}}"));
  CHECK(error_of([&] { import(sparse); }) ==
        sparse + ":8: accessor 1: its sparse values run past its buffer view of 36 bytes (offset 24, 2 x 12 bytes "
                 "apart; assimp 5.2.5 would read past it)");
}

TEST_CASE("model messages: glTF is read with assimp's defaults and strides, and as one JSON reading", "[frontend]") {
  // No componentType: assimp reads BYTE; 3 VEC3 bytes 4 apart from byte 30 end at 41.
  const std::string bytes = temp_file("bytes.gltf", gltf_triangle("\n{\"bufferView\": 0, \"componentType\": 5126, "
                                                                   "\"count\": 3, \"type\": \"VEC3\"}",
                                                                   ",\n{\"bufferView\": 0, \"byteOffset\": 30, "
                                                                   "\"count\": 3, \"type\": \"VEC3\"}"));
  CHECK(error_of([&] { import(bytes); }) ==
        bytes + ":8: accessor 1: its elements run past its buffer view of 36 bytes (offset 30, 3 x 3 bytes apart; "
                "assimp 5.2.5 would read past it)");
  // glTF 2: an accessor's own byteStride is not read (the view's is): 3 x 12 bytes fit the 36.
  const std::string own = temp_file("ownstride.gltf", gltf_triangle("\n{\"bufferView\": 0, \"byteStride\": 24, "
                                                                    "\"componentType\": 5126, \"count\": 3, "
                                                                    "\"type\": \"VEC3\", \"min\": [0, 0, 0], "
                                                                    "\"max\": [1, 1, 0]}"));
  CHECK(import(own).mesh.polygon_count() == 1);
  // A view's stride below the element's size.
  std::string narrow = gltf_triangle("\n{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\"}");
  narrow.replace(narrow.find("\"byteLength\": 36}]"), 18, "\"byteLength\": 36, \"byteStride\": 4}]");
  const std::string stride = temp_file("narrow.gltf", narrow);
  CHECK(error_of([&] { import(stride); }) ==
        stride + ":7: accessor 0: a stride of 4 bytes, less than its elements' 12 (glTF asks for at least that; "
                 "assimp 5.2.5 reads past the view)");
  // A key given twice: assimp's RapidJSON keeps the first (here an offset of 12, past the view), nlohmann the last.
  const std::string twice = temp_file("twice.gltf", gltf_triangle("\n{\"bufferView\": 0, \"byteOffset\": 12, "
                                                                  "\"byteOffset\": 0, \"componentType\": 5126, "
                                                                  "\"count\": 3, \"type\": \"VEC3\"}"));
  CHECK(error_of([&] { import(twice); }) ==
        twice + ":7: the key \"byteOffset\" twice in one object (assimp 5.2.5 reads the first, this check the last)");
  // Text that is not JSON (a byte of no UTF-8 character in a string): refused, not passed over.
  std::string latin = gltf_triangle("\n{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\"}");
  latin.replace(latin.find("\"2.0\"}"), 7, "\"2.0\", \"extras\": \"\xff\"}");
  const std::string bad = temp_file("latin.gltf", latin);
  CHECK(error_of([&] { import(bad); }).rfind(bad + ": not JSON as glTF asks: ", 0) == 0);
}

TEST_CASE("model messages: glTF 1 views, ids and accessor strides are checked the same way", "[frontend]") {
  // glTF 1.0: collections keyed by id, the stride on the accessor, a buffer's byteLength optional.
  auto gltf1 = [](const std::string& accessor, const std::string& buffer_length) {
    return "{\"asset\": {\"version\": \"1.0\"},\n"
           "\"buffers\": {\"data\": {" + buffer_length + "\"uri\": \"data:application/octet-stream;base64,"
           "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}},\n"
           "\"bufferViews\": {\"v/1\": {\"buffer\": \"data\", \"byteLength\": 36}},\n"
           "\"accessors\": {\n\"pos\": " + accessor + "\n}}\n";
  };
  const std::string strided = temp_file("v1stride.gltf", gltf1("{\"bufferView\": \"v/1\", \"byteStride\": 16, "
                                                               "\"componentType\": 5126, \"count\": 3, "
                                                               "\"type\": \"VEC3\"}", "\"byteLength\": 36, "));
  CHECK(error_of([&] { import(strided); }) ==
        strided + ":5: accessor pos: its elements run past its buffer view of 36 bytes (offset 0, 3 x 16 bytes apart; "
                  "assimp 5.2.5 would read past it)");
  // A view past a buffer that gives its length; none checked where it does not.
  const std::string shorter = temp_file("v1short.gltf", gltf1("{\"bufferView\": \"v/1\", \"componentType\": 5126, "
                                                              "\"count\": 3, \"type\": \"VEC3\"}",
                                                              "\"byteLength\": 24, "));
  CHECK(error_of([&] { import(shorter); }) ==
        shorter + ":3: buffer view v/1: bytes 0 to 36 of buffer data of 24 bytes (a view lies within its buffer; "
                  "assimp 5.2.5's glTF 1 reader reads past it)");
  const std::string unsized = temp_file("v1unsized.gltf", gltf1("{\"bufferView\": \"v/1\", \"componentType\": 5126, "
                                                                "\"count\": 3, \"type\": \"VEC3\"}", ""));
  CHECK(error_of([&] { import(unsized); }).find("buffer view") == std::string::npos);
}
