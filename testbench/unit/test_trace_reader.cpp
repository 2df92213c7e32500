// Unit tests for the trace reader and writer (sim/io/trace_reader.hpp,
// sim/io/trace_writer.hpp) against traces/FORMAT.md.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "config/params.hpp"
#include "io/trace.hpp"
#include "io/trace_reader.hpp"
#include "io/trace_writer.hpp"

namespace girtd {
namespace {

namespace fs = std::filesystem;

const char* const kTri1 = "tri 100 100 1000 255 0 0 1   300 120 1000 255 0 0 1   180 300 1000 255 0 0 1";
const char* const kTri2 = "tri 150.5 80 2000 0 0 255 0.5   320 260 2000 0 10 255 1   90 280.25 2000 0 0 255 0";

Trace read_text(const std::string& text, std::optional<TraceLevel> forced = std::nullopt) {
  std::istringstream in(text);
  return read_trace(in, "test.trace", forced, Params::defaults());
}

struct Failure {
  int line = -1;
  std::string what;
  std::string file;
};

// Reads `text`, which must fail with an InputError.
Failure read_failure(const std::string& text, std::optional<TraceLevel> forced = std::nullopt,
                     const Params& params = Params::defaults()) {
  std::istringstream in(text);
  try {
    read_trace(in, "test.trace", forced, params);
  } catch (const InputError& e) {
    return Failure{e.line(), e.what(), e.file()};
  }
  FAIL("trace was accepted:\n" << text);
  return {};
}

// A unique path in the temp directory, removed (with its .partial) on scope exit.
struct TempPath {
  fs::path path;
  explicit TempPath(const std::string& name)
      : path(fs::temp_directory_path() / ("girtd_unit_" + std::to_string(::getpid()) + "_" + name)) {
    cleanup();
  }
  ~TempPath() { cleanup(); }
  void cleanup() {
    std::error_code ec;
    fs::remove(path, ec);
    fs::remove(path.string() + ".partial", ec);
  }
  std::string str() const { return path.string(); }
};

Vertex vtx(double x, double y, double z, double r, double g, double b, double t) {
  Vertex v;
  v.x = x;
  v.y = y;
  v.z = z;
  v.r = r;
  v.g = g;
  v.b = b;
  v.t = t;
  return v;
}

void check_vertex_equal(const Vertex& a, const Vertex& b) {
  CHECK(a.x == b.x);
  CHECK(a.y == b.y);
  CHECK(a.z == b.z);
  CHECK(a.r == b.r);
  CHECK(a.g == b.g);
  CHECK(a.b == b.b);
  CHECK(a.t == b.t);
}

}  // namespace

TEST_CASE("trace reader parses header, settings and triangles", "[trace]") {
  const Trace t = read_text(
      "girtd-trace 1 triangle\n"        // 1
      "# a comment line\n"              // 2
      "\n"                              // 3
      "background 20 21 40  # trail\n"  // 4
      "   q 0.5\n"                       // 5
      "window 10 20 500 600\n"          // 6
      + std::string(kTri1) + "\n"       // 7
      + std::string(kTri2) + "\n");     // 8
  CHECK(t.path == "test.trace");
  CHECK(t.level == TraceLevel::kTriangle);
  REQUIRE(t.frames.size() == 1);
  CHECK(t.primitive_count() == 2);
  const TraceFrame& f = t.frames[0];
  CHECK(f.settings.background == Rgb{20, 21, 40});
  CHECK(f.settings.q == 0.5);
  CHECK(f.settings.q_line == 5);
  CHECK(f.settings.window.x0 == 10);
  CHECK(f.settings.window.y0 == 20);
  CHECK(f.settings.window.x1 == 500);
  CHECK(f.settings.window.y1 == 600);
  REQUIRE(f.triangles.size() == 2);
  CHECK(f.dda.empty());
  CHECK(f.triangles[0].source_line == 7);
  CHECK(f.triangles[1].source_line == 8);
  check_vertex_equal(f.triangles[0].v[0], vtx(100, 100, 1000, 255, 0, 0, 1));
  check_vertex_equal(f.triangles[0].v[1], vtx(300, 120, 1000, 255, 0, 0, 1));
  check_vertex_equal(f.triangles[0].v[2], vtx(180, 300, 1000, 255, 0, 0, 1));
  check_vertex_equal(f.triangles[1].v[0], vtx(150.5, 80, 2000, 0, 0, 255, 0.5));
  check_vertex_equal(f.triangles[1].v[1], vtx(320, 260, 2000, 0, 10, 255, 1));
  check_vertex_equal(f.triangles[1].v[2], vtx(90, 280.25, 2000, 0, 0, 255, 0));
}

TEST_CASE("trace reader defaults and settings carried across frames", "[trace]") {
  const Trace t = read_text(
      "girtd-trace 1 triangle\n"
      + std::string(kTri1) + "\n"   // frame 0: defaults
      "frame\n"
      "q 2\n"
      "background 1 2 3\n"
      + std::string(kTri1) + "\n"   // frame 1: q 2, background 1 2 3
      "frame\n"
      "window 0 0 99 99\n"
      + std::string(kTri2) + "\n"   // frame 2: q, background carried; new window
      + std::string(kTri1) + "\n");
  REQUIRE(t.frames.size() == 3);
  CHECK(t.primitive_count() == 4);
  // Frame 0: FORMAT.md defaults window 0 0 1023 1023, background 0 0 0, q 1.
  const FrameSettings& s0 = t.frames[0].settings;
  CHECK(s0.window.x0 == 0);
  CHECK(s0.window.y0 == 0);
  CHECK(s0.window.x1 == 1023);
  CHECK(s0.window.y1 == 1023);
  CHECK(s0.background == Rgb{0, 0, 0});
  CHECK(s0.q == 1.0);
  const FrameSettings& s1 = t.frames[1].settings;
  CHECK(s1.q == 2.0);
  CHECK(s1.background == Rgb{1, 2, 3});
  CHECK(s1.window.x1 == 1023);
  const FrameSettings& s2 = t.frames[2].settings;
  CHECK(s2.q == 2.0);
  CHECK(s2.background == Rgb{1, 2, 3});
  CHECK(s2.window.x1 == 99);
  CHECK(s2.window.y1 == 99);
  CHECK(t.frames[0].triangles.size() == 1);
  CHECK(t.frames[1].triangles.size() == 1);
  CHECK(t.frames[2].triangles.size() == 2);
  CHECK(t.frames[2].triangles[0].source_line == 9);
}

TEST_CASE("trace reader accepts a headerless file when the level is forced", "[trace]") {
  const Trace t = read_text("# no header\n\n" + std::string(kTri1) + "\n", TraceLevel::kTriangle);
  CHECK(t.level == TraceLevel::kTriangle);
  REQUIRE(t.frames.size() == 1);
  REQUIRE(t.frames[0].triangles.size() == 1);
  CHECK(t.frames[0].triangles[0].source_line == 3);
  // A forced level equal to the header's is fine too.
  const Trace u = read_text("girtd-trace 1 triangle\n" + std::string(kTri1) + "\n", TraceLevel::kTriangle);
  CHECK(u.primitive_count() == 1);
  // No trailing newline on the last line.
  const Trace w = read_text("girtd-trace 1 triangle\n" + std::string(kTri1));
  CHECK(w.primitive_count() == 1);
}

TEST_CASE("trace reader rejects a wrong field count with its line", "[trace]") {
  const Failure f = read_failure("girtd-trace 1 triangle\n\ntri 1 2 3 4 5 6 7\n");
  CHECK(f.line == 3);
  CHECK(f.file == "test.trace");
  CHECK_THAT(f.what, Catch::Contains("21"));
  // 24 numbers is wrong too (21, then INTERIOR and SURFACE at most).
  const Failure g = read_failure("girtd-trace 1 triangle\n" + std::string(kTri1) + " 5 1 2\n");
  CHECK(g.line == 2);
  CHECK_THAT(g.what, Catch::Contains("21"));
  // INTERIOR is a 3-bit mask.
  const Failure i = read_failure("girtd-trace 1 triangle\n" + std::string(kTri1) + " 8\n");
  CHECK(i.line == 2);
  CHECK_THAT(i.what, Catch::Contains("INTERIOR = 8 is outside 0..7"));
  // window with 3 fields.
  const Failure h = read_failure("girtd-trace 1 triangle\nwindow 0 0 100\n" + std::string(kTri1) + "\n");
  CHECK(h.line == 2);
}

TEST_CASE("trace reader rejects non-numbers, NaN and infinity", "[trace]") {
  const Failure a =
      read_failure("girtd-trace 1 triangle\ntri 100 1O0 1000 255 0 0 1 300 120 1000 255 0 0 1 180 300 1000 255 0 0 1\n");
  CHECK(a.line == 2);
  CHECK_THAT(a.what, Catch::Contains("not a number"));
  CHECK_THAT(a.what, Catch::Contains("1O0"));
  const Failure b =
      read_failure("girtd-trace 1 triangle\n#\ntri nan 100 1000 255 0 0 1 300 120 1000 255 0 0 1 180 300 1000 255 0 0 1\n");
  CHECK(b.line == 3);
  CHECK_THAT(b.what, Catch::Contains("not finite"));
  const Failure c =
      read_failure("girtd-trace 1 triangle\ntri 100 100 1000 255 0 0 1 inf 120 1000 255 0 0 1 180 300 1000 255 0 0 1\n");
  CHECK(c.line == 2);
  CHECK_THAT(c.what, Catch::Contains("not finite"));
  // 1e999 overflows to infinity.
  const Failure d =
      read_failure("girtd-trace 1 triangle\ntri 100 100 1000 255 0 0 1 1e999 120 1000 255 0 0 1 180 300 1000 255 0 0 1\n");
  CHECK(d.line == 2);
  // An integer field given a fraction.
  const Failure e = read_failure("girtd-trace 1 triangle\nbackground 1.5 0 0\n" + std::string(kTri1) + "\n");
  CHECK(e.line == 2);
  CHECK_THAT(e.what, Catch::Contains("not an integer"));
}

TEST_CASE("trace reader accepts tiny finite numbers that underflow to subnormals", "[trace]") {
  // 1e-310 is a finite decimal (a subnormal double, 1e-310 > 4.9e-324); FORMAT.md
  // only forbids NaN and Inf. strtod sets ERANGE for it, but the value is exact
  // enough and finite, so it must be read, not rejected as "not finite".
  const Trace t = read_text("girtd-trace 1 triangle\ntri 1e-310 0 0 0 0 0 1  10 0 0 0 0 0 1  0 10 0 0 0 0 1\n");
  REQUIRE(t.primitive_count() == 1);
  CHECK(t.frames[0].triangles[0].v[0].x == 1e-310);
  // And what TraceWriter writes (17 significant digits) must read back.
  TempPath tmp("subnormal.trace");
  Triangle a;
  a.v = {vtx(1e-310, 0, 0, 0, 0, 0, 1), vtx(10, 0, 0, 0, 0, 0, 1), vtx(0, 10, 0, 0, 0, 0, 1)};
  {
    TraceWriter w(tmp.str(), TraceLevel::kTriangle, Params::defaults(), "");
    w.begin_frame(FrameSettings{});
    w.write(a);
    w.commit();
  }
  const Trace u = read_trace(tmp.str(), std::nullopt, Params::defaults());
  REQUIRE(u.primitive_count() == 1);
  CHECK(u.frames[0].triangles[0].v[0].x == 1e-310);
}

TEST_CASE("trace reader rejects out-of-range colour, T and depth", "[trace]") {
  const Failure a =
      read_failure("girtd-trace 1 triangle\ntri 100 100 1000 256 0 0 1 300 120 1000 255 0 0 1 180 300 1000 255 0 0 1\n");
  CHECK(a.line == 2);
  CHECK_THAT(a.what, Catch::Contains("R = 256"));
  const Failure b =
      read_failure("girtd-trace 1 triangle\ntri 100 100 1000 255 0 0 1 300 120 1000 255 0 0 1.0001 180 300 1000 255 0 0 1\n");
  CHECK(b.line == 2);
  CHECK_THAT(b.what, Catch::Contains("T = 1.0001"));
  const Failure c =
      read_failure("girtd-trace 1 triangle\ntri 100 100 -1 255 0 0 1 300 120 1000 255 0 0 1 180 300 1000 255 0 0 1\n");
  CHECK_THAT(c.what, Catch::Contains("Z = -1"));
  const Failure d = read_failure("girtd-trace 1 triangle\nbackground 0 256 0\n" + std::string(kTri1) + "\n");
  CHECK(d.line == 2);
  CHECK_THAT(d.what, Catch::Contains("G = 256"));
  const Failure e = read_failure("girtd-trace 1 triangle\nwindow 0 0 1024 100\n" + std::string(kTri1) + "\n");
  CHECK(e.line == 2);
  CHECK_THAT(e.what, Catch::Contains("X1 = 1024"));
  const Failure g = read_failure("girtd-trace 1 triangle\nq -1\n" + std::string(kTri1) + "\n");
  CHECK(g.line == 2);
}

TEST_CASE("trace reader rejects an unknown record", "[trace]") {
  const Failure f = read_failure("girtd-trace 1 triangle\n" + std::string(kTri1) + "\ntirangle 1 2 3\n");
  CHECK(f.line == 3);
  CHECK_THAT(f.what, Catch::Contains("unknown record 'tirangle'"));
  // A second header is not a record either.
  const Failure g = read_failure("girtd-trace 1 triangle\n" + std::string(kTri1) + "\ngirtd-trace 1 triangle\n");
  CHECK(g.line == 3);
}

TEST_CASE("trace reader rejects settings after the first primitive of a frame", "[trace]") {
  const Failure f = read_failure("girtd-trace 1 triangle\n" + std::string(kTri1) + "\nq 1\n");
  CHECK(f.line == 3);
  CHECK_THAT(f.what, Catch::Contains("before the first primitive"));
  const Failure g =
      read_failure("girtd-trace 1 triangle\n" + std::string(kTri1) + "\nframe\n" + kTri1 + "\nbackground 1 1 1\n");
  CHECK(g.line == 5);
  const Failure h = read_failure("girtd-trace 1 triangle\n" + std::string(kTri1) + "\nwindow 0 0 10 10\n");
  CHECK(h.line == 3);
}

TEST_CASE("trace reader rejects dda records in a triangle trace", "[trace]") {
  const Failure f = read_failure("girtd-trace 1 triangle\n" + std::string(kTri1) + "\ndda 0 0 0 0 0\n");
  CHECK(f.line == 3);
  CHECK_THAT(f.what, Catch::Contains("dda"));
  CHECK_THAT(f.what, Catch::Contains("triangle"));
  // And the opposite: a tri in a dda trace.
  const Failure g = read_failure("girtd-trace 1 dda\n" + std::string(kTri1) + "\n");
  CHECK(g.line == 2);
  CHECK_THAT(g.what, Catch::Contains("tri"));
}

TEST_CASE("trace reader header errors: missing, version 2, contradicting level", "[trace]") {
  // No header and no forced level: reported at the first record (line 3).
  const Failure a = read_failure("# comment\n\n" + std::string(kTri1) + "\n");
  CHECK(a.line == 3);
  CHECK_THAT(a.what, Catch::Contains("header"));
  const Failure b = read_failure("girtd-trace 2 triangle\n" + std::string(kTri1) + "\n");
  CHECK(b.line == 1);
  CHECK_THAT(b.what, Catch::Contains("version 2"));
  const Failure c = read_failure("\ngirtd-trace 1 triangle\n" + std::string(kTri1) + "\n", TraceLevel::kDda);
  CHECK(c.line == 2);
  CHECK_THAT(c.what, Catch::Contains("contradicts"));
  const Failure d = read_failure("girtd-trace 1 pixel\n" + std::string(kTri1) + "\n");
  CHECK(d.line == 1);
  CHECK_THAT(d.what, Catch::Contains("pixel"));
  const Failure e = read_failure("girtd-trace 1\n" + std::string(kTri1) + "\n");
  CHECK(e.line == 1);
}

TEST_CASE("trace reader rejects empty traces", "[trace]") {
  const Failure a = read_failure("");
  CHECK(a.line == 0);
  CHECK_THAT(a.what, Catch::Contains("empty"));
  const Failure b = read_failure("# only a comment\n\n   \n");
  CHECK(b.line == 0);
  CHECK_THAT(b.what, Catch::Contains("empty"));
  // A header and settings but no primitive.
  const Failure c = read_failure("girtd-trace 1 triangle\nq 1\n");
  CHECK_THAT(c.what, Catch::Contains("no primitives"));
}

TEST_CASE("trace reader rejects an empty window", "[trace]") {
  const Failure a = read_failure("girtd-trace 1 triangle\n\nwindow 500 0 100 1023\n" + std::string(kTri1) + "\n");
  CHECK(a.line == 3);
  CHECK_THAT(a.what, Catch::Contains("window is empty"));
  const Failure b = read_failure("girtd-trace 1 triangle\nwindow 0 600 1023 599\n" + std::string(kTri1) + "\n");
  CHECK(b.line == 2);
  // X0 == X1 is a one-column window, which is fine.
  const Trace t = read_text("girtd-trace 1 triangle\nwindow 7 0 7 1023\n" + std::string(kTri1) + "\n");
  CHECK(t.frames[0].settings.window.x0 == 7);
  CHECK(t.frames[0].settings.window.x1 == 7);
}

TEST_CASE("trace writer and reader round-trip a triangle trace exactly", "[trace]") {
  TempPath tmp("roundtrip_tri.trace");
  const Params params = Params::defaults();
  FrameSettings s1;
  s1.window = Window{1, 2, 1000, 1001};
  s1.background = Rgb{10, 200, 255};
  s1.q = 0.0625;
  FrameSettings s2 = s1;
  s2.q = 0;
  s2.background = Rgb{0, 0, 1};
  Triangle a;
  a.v = {vtx(0.1, 1.0 / 3.0, 65535, 255, 0, 1e-7, 1), vtx(511.99999999999994, -12.5, 0.3, 0.1, 254.9, 7, 0.7),
         vtx(-999999.5, 1e6, 12345.678901234567, 128.125, 33.3, 66.6, 0)};
  Triangle b;
  b.v = {vtx(3, 4, 5, 6, 7, 8, 0.25), vtx(2.0 / 3.0, 9.999999999999998, 100, 0, 0, 0, 1),
         vtx(1023.5, 1023.25, 65534.99, 1, 2, 3, 0.123456789012345678)};
  {
    TraceWriter w(tmp.str(), TraceLevel::kTriangle, params, "unit test");
    w.begin_frame(s1);
    w.write(a);
    w.write(b);
    w.begin_frame(s2);
    w.write(b);
    w.commit();
  }
  REQUIRE(fs::exists(tmp.path));
  CHECK_FALSE(fs::exists(tmp.str() + ".partial"));
  CHECK(has_trace_header(tmp.str()));
  const Trace t = read_trace(tmp.str(), std::nullopt, params);
  CHECK(t.level == TraceLevel::kTriangle);
  REQUIRE(t.frames.size() == 2);
  const FrameSettings& r1 = t.frames[0].settings;
  CHECK(r1.window.x0 == 1);
  CHECK(r1.window.y0 == 2);
  CHECK(r1.window.x1 == 1000);
  CHECK(r1.window.y1 == 1001);
  CHECK(r1.background == Rgb{10, 200, 255});
  CHECK(r1.q == 0.0625);
  CHECK(t.frames[1].settings.q == 0.0);
  CHECK(t.frames[1].settings.background == Rgb{0, 0, 1});
  REQUIRE(t.frames[0].triangles.size() == 2);
  REQUIRE(t.frames[1].triangles.size() == 1);
  for (int i = 0; i < 3; ++i) {
    check_vertex_equal(t.frames[0].triangles[0].v[i], a.v[i]);
    check_vertex_equal(t.frames[0].triangles[1].v[i], b.v[i]);
    check_vertex_equal(t.frames[1].triangles[0].v[i], b.v[i]);
  }
}

TEST_CASE("trace writer and reader round-trip a dda trace exactly", "[trace]") {
  TempPath tmp("roundtrip_dda.trace");
  const Params params = Params::defaults();
  // Register extremes of the default formats: colour/T 20 bits (+-2^19),
  // Z 26 bits (+-2^25), D 24 bits (+-2^23).
  DdaParams d1;
  d1.x0 = 5;
  d1.y0 = 6;
  d1.xmin = 0;
  d1.xmax = 1023;
  d1.ymax = 1023;
  d1.q = 0.25;
  for (int e = 0; e < kEpCount; ++e) d1.ep[e] = EpInit{e * 1000 - 3, -e, e * 7};
  d1.ep[kEpR] = EpInit{524287, -524288, 1};
  d1.ep[kEpZ] = EpInit{33554431, -33554432, -1};
  d1.ep[kEpD3] = EpInit{8388607, -8388608, 0};
  DdaParams d2 = d1;
  d2.x0 = 100;
  d2.xmin = 100;
  d2.xmax = 100;
  d2.y0 = 1023;
  d2.ymax = 1023;
  d2.q = 0;
  d2.ep[kEpT] = EpInit{256 * 512, 0, 0};
  FrameSettings s1;
  s1.q = 0.25;
  FrameSettings s2;
  s2.q = 0;
  s2.background = Rgb{9, 8, 7};
  {
    TraceWriter w(tmp.str(), TraceLevel::kDda, params, "");
    w.begin_frame(s1);
    w.write(d1);
    w.begin_frame(s2);
    w.write(d2);
    w.write(d1);  // d1 under q = 0 reads back with q = 0
    w.commit();
  }
  const Trace t = read_trace(tmp.str(), std::nullopt, params);
  CHECK(t.level == TraceLevel::kDda);
  REQUIRE(t.frames.size() == 2);
  REQUIRE(t.frames[0].dda.size() == 1);
  REQUIRE(t.frames[1].dda.size() == 2);
  CHECK(t.frames[0].triangles.empty());
  CHECK(t.frames[0].dda[0] == d1);
  CHECK(t.frames[1].dda[0] == d2);
  DdaParams d1_q0 = d1;
  d1_q0.q = 0;
  CHECK(t.frames[1].dda[1] == d1_q0);
  CHECK(t.frames[1].settings.background == Rgb{9, 8, 7});
  // The file names the formats it was made for.
  CHECK(dda_format_record(params) == "format color 11 9 8 t 11 9 8 z 18 8 16 d 12 12 xy 16");
}

TEST_CASE("trace writer destroyed without commit leaves no file", "[trace]") {
  TempPath tmp("uncommitted.trace");
  {
    TraceWriter w(tmp.str(), TraceLevel::kTriangle, Params::defaults(), "never committed");
    w.begin_frame(FrameSettings{});
    Triangle a;
    a.v = {vtx(0, 0, 0, 0, 0, 0, 1), vtx(10, 0, 0, 0, 0, 0, 1), vtx(0, 10, 0, 0, 0, 0, 1)};
    w.write(a);
  }
  CHECK_FALSE(fs::exists(tmp.path));
  CHECK_FALSE(fs::exists(tmp.str() + ".partial"));
}

TEST_CASE("dda trace made for other EP formats is rejected", "[trace]") {
  // A hand-written trace whose colour EP is 12.9: line 2 names other formats.
  std::string dda_line = "dda 0 0 0 10 10";
  for (int e = 0; e < kEpCount; ++e) dda_line += " 0 0 0";
  const Failure a = read_failure("girtd-trace 1 dda\nformat color 12 9 8 t 11 9 8 z 18 8 16 d 12 12 xy 16\n" +
                                 dda_line + "\n");
  CHECK(a.line == 2);
  CHECK_THAT(a.what, Catch::Contains("other EP formats"));
  // The matching format reads fine.
  const Trace ok = read_text("girtd-trace 1 dda\nformat color 11 9 8 t 11 9 8 z 18 8 16 d 12 12 xy 16\n" + dda_line +
                             "\n");
  CHECK(ok.primitive_count() == 1);
  // A trace written with the defaults, read under a configuration with 12-bit colour integers.
  TempPath tmp("other_format.trace");
  {
    TraceWriter w(tmp.str(), TraceLevel::kDda, Params::defaults(), "");
    w.begin_frame(FrameSettings{});
    DdaParams d;
    d.xmax = 10;
    d.ymax = 10;
    w.write(d);
    w.commit();
  }
  const Params wide = Params::with_overrides(nlohmann::json{{"ep", {{"color", {{"int_bits", 12}}}}}}, "wide.json");
  try {
    read_trace(tmp.str(), std::nullopt, wide);
    FAIL("dda trace with other formats was accepted");
  } catch (const InputError& e) {
    CHECK(e.line() == 2);  // line 1 header, line 2 format
    CHECK_THAT(std::string(e.what()), Catch::Contains("other EP formats"));
  }
}

TEST_CASE("dda trace values must fit their registers and follow the format record", "[trace]") {
  const std::string fmt = "format color 11 9 8 t 11 9 8 z 18 8 16 d 12 12 xy 16\n";
  auto dda_with_d1 = [](const std::string& d1) {
    std::string s = "dda 0 0 0 10 10";
    for (int e = 0; e < kEpCount; ++e) s += (e == kEpD1) ? " " + d1 + " 0 0" : " 0 0 0";
    return s + "\n";
  };
  // D 12.12 is 24 bits: 2^23 - 1 = 8388607 fits, 8388608 does not.
  CHECK(read_text("girtd-trace 1 dda\n" + fmt + dda_with_d1("8388607")).primitive_count() == 1);
  const Failure a = read_failure("girtd-trace 1 dda\n" + fmt + dda_with_d1("8388608"));
  CHECK(a.line == 3);
  CHECK_THAT(a.what, Catch::Contains("D1"));
  // dda before format.
  const Failure b = read_failure("girtd-trace 1 dda\n" + dda_with_d1("0"));
  CHECK(b.line == 2);
  CHECK_THAT(b.what, Catch::Contains("format"));
  // The DDA takes only Q = 0 or a power of two: q 0.3 is refused at the dda record.
  const Failure c = read_failure("girtd-trace 1 dda\n" + fmt + "q 0.3\n" + dda_with_d1("0"));
  CHECK(c.line == 4);
}

TEST_CASE("a triangle's interior edges and surface are optional fields", "[trace]") {
  const Trace t = read_text("girtd-trace 1 triangle\n" + std::string(kTri1) + "\n" + kTri1 + " 5\n" + kTri1 +
                            " 2 17\n");
  const auto& tris = t.frames.at(0).triangles;
  REQUIRE(tris.size() == 3);
  CHECK(tris[0].interior_edges == 0);
  CHECK(tris[0].surface == -1);
  CHECK(tris[1].interior_edges == 5);
  CHECK(tris[1].surface == -1);
  CHECK(tris[2].interior_edges == 2);
  CHECK(tris[2].surface == 17);
}

}  // namespace girtd
