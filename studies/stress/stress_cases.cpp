#include "stress/stress_cases.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "frontend/interior_edges.hpp"
#include "girtd/design_constants.hpp"

namespace girtd {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vertex vtx(double x, double y, double z, double r, double g, double b, double t = 1) { return {x, y, z, r, g, b, t}; }

Triangle tri(const Vertex& a, const Vertex& b, const Vertex& c, int surface = -1) {
  Triangle t;
  t.v = {a, b, c};
  t.surface = surface;
  return t;
}

std::string number(double v) {  // exact, for traces
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string label(double v) {  // short, for names
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

StressCase trace_case(const std::string& family, const std::string& name, const std::string& what, bool fast,
                      const std::vector<Triangle>& tris, double q) {
  return {family, family + "_" + name, what, fast, false, triangle_trace(tris, q, what), {}};
}

// One screen-covering triangle, its corners `o` px beyond the screen, and a
// sliver crossing the screen from 2 x `o` px away.
std::vector<StressCase> huge() {
  std::vector<StressCase> out;
  for (double o : {1500.0, 2500.0, 10000.0, 100000.0, 1000000.0}) {
    const double far = std::min(1e6, 2 * o + 3000);  // the input limit is 1e6
    const std::string n = label(o);
    const bool fast = o == 1500 || o == 1e6;
    const double lo = -o, hi = std::min(kScreenWidth - 1 + o, 1e6);  // the input limit is 1e6
    out.push_back(trace_case("huge", "cover_" + n, "screen-filling triangle, corners " + n + " px beyond the screen",
                             fast,
                             {tri(vtx(lo, lo, 30000, 200, 100, 50), vtx(hi, lo, 30000, 200, 100, 50),
                                  vtx(511.5, hi, 30000, 200, 100, 50))},
                             0));
    out.push_back(trace_case("huge", "sliver_" + n, "a 20-px band across the screen from " + label(far) + " px away",
                             o == 1e6,
                             {tri(vtx(-far, 500, 1000, 0, 0, 255), vtx(far, 505, 60000, 255, 0, 0),
                                  vtx(far, 525, 60000, 255, 255, 0))},
                             1));
  }
  return out;
}

// 1000:1, sub-pixel wide, at every 15 degrees, with and without antialiasing.
std::vector<StressCase> sliver() {
  std::vector<StressCase> out;
  for (double width : {0.3, 0.9})
    for (double q : {0.0, 1.0})
      for (int deg = 0; deg < 180; deg += 15) {
        const double a = deg * kPi / 180, len = 300 * width * 1000 / 300;  // aspect 1000:1
        const double cx = 511.3, cy = 509.7, ux = std::cos(a), uy = std::sin(a), nx = -uy * width, ny = ux * width;
        const Triangle t = tri(vtx(cx - ux * len / 2, cy - uy * len / 2, 20000, 255, 255, 255),
                               vtx(cx + ux * len / 2, cy + uy * len / 2, 20000, 255, 255, 255),
                               vtx(cx + ux * len / 2 + nx, cy + uy * len / 2 + ny, 20000, 255, 255, 255));
        const std::string n = "w" + label(width) + "_q" + label(q) + "_" + std::to_string(deg);
        out.push_back(trace_case("sliver", n, "aspect 1000:1, " + label(width) + " px wide, at " +
                                                  std::to_string(deg) + " deg, Q " + label(q),
                                 deg % 60 == 0 && width == 0.3, {t}, q));
      }
  return out;
}

std::vector<StressCase> degenerate() {
  std::vector<Triangle> collinear, tiny, repeated;
  for (int k = 0; k < 8; ++k) {
    const double x = 100 + 110 * k, y = 200 + 13 * k;
    // Collinear within 1e-6 px: the third corner 1e-7 px off the line.
    collinear.push_back(tri(vtx(x, y, 1000, 255, 0, 0), vtx(x + 80, y + 40, 1000, 255, 0, 0),
                            vtx(x + 40, y + 20 + 1e-7 * (k + 1), 1000, 255, 0, 0)));
    // Area under one lattice cell, at fractional positions around lattice points.
    const double fx = 0.13 * k, fy = 0.29 * k - 0.5;
    tiny.push_back(tri(vtx(x + fx, 600 + fy, 1000, 0, 255, 0), vtx(x + fx + 0.7, 600 + fy + 0.1, 1000, 0, 255, 0),
                       vtx(x + fx + 0.2, 600 + fy + 0.8, 1000, 0, 255, 0)));
    repeated.push_back(tri(vtx(x, 800, 1000, 0, 0, 255), vtx(x, 800, 1000, 0, 0, 255), vtx(x + 30, 830, 1000, 0, 0, 255)));
  }
  return {trace_case("degenerate", "collinear_q0", "collinear within 1e-7 px, Q 0", true, collinear, 0),
          trace_case("degenerate", "collinear_q1", "collinear within 1e-7 px, Q 1", false, collinear, 1),
          trace_case("degenerate", "tiny_q0", "area under one lattice cell, Q 0", true, tiny, 0),
          trace_case("degenerate", "tiny_q1", "area under one lattice cell, Q 1", false, tiny, 1),
          trace_case("degenerate", "repeated_corner", "two corners the same", false, repeated, 1)};
}

std::vector<StressCase> subpixel() {
  std::vector<StressCase> out;
  for (double q : {0.0, 0.5, 1.0}) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> pos(50, 970), size(0.1, 0.95), frac(0, 1);
    std::vector<Triangle> tris;
    for (int k = 0; k < 60; ++k) {
      const double x = pos(rng), y = pos(rng), s = size(rng);
      tris.push_back(tri(vtx(x, y, 1000 + k, 255, 200, 100), vtx(x + s, y + s * frac(rng), 1000 + k, 255, 200, 100),
                         vtx(x + s * frac(rng), y + s, 1000 + k, 255, 200, 100)));
    }
    out.push_back(trace_case("subpixel", "q" + label(q), "60 triangles under a pixel, Q " + label(q), q == 1, tris, q));
  }
  return out;
}

// Attributes 0..255 and 0..65534 across one pixel, far from the origin.
std::vector<StressCase> steep() {
  std::vector<StressCase> out;
  for (double q : {0.0, 1.0}) {
    const double x = 1000.25, y = 1000.5;
    const Triangle colour = tri(vtx(x, y, 1000, 0, 255, 0), vtx(x + 1, y, 1000, 255, 0, 0), vtx(x, y + 20, 1000, 0, 255, 255));
    const Triangle depth = tri(vtx(x - 40, y, 0, 255, 255, 255), vtx(x - 39, y, 65534, 255, 255, 255),
                               vtx(x - 40, y + 20, 0, 255, 255, 255));
    const Triangle both = tri(vtx(900.5, 990, 0, 0, 0, 0), vtx(900.5, 991, 65534, 255, 255, 255),
                              vtx(1020, 990.2, 65534, 255, 255, 255));
    out.push_back(trace_case("steep", "q" + label(q), "colour 0..255 and Z 0..65534 across one pixel near (1000, 1000), Q " + label(q),
                             q == 1, {depth, colour, both}, q));
  }
  return out;
}

// Z at both ends of its range, the fringe reaching past them.
std::vector<StressCase> zrange() {
  std::vector<StressCase> out;
  for (double q : {0.0, 1.0, 4.0, 8.0}) {
    const std::vector<Triangle> tris = {
        tri(vtx(100, 100, 65534, 255, 0, 0), vtx(900, 150, 65534, 255, 0, 0), vtx(400, 900, 65534, 255, 0, 0)),
        tri(vtx(200, 120, 0, 0, 255, 0), vtx(800, 300, 0, 0, 255, 0), vtx(300, 700, 0, 0, 255, 0)),
        tri(vtx(600, 500, 0, 0, 0, 255), vtx(1000, 520, 65534, 0, 0, 255), vtx(620, 1000, 0, 0, 0, 255))};
    out.push_back(trace_case("zrange", "q" + label(q), "Z 0 and 65534, and a ramp 0..65534, Q " + label(q), q == 8 || q == 1,
                             tris, q));
  }
  return out;
}

// Every vertex order and both windings of the same two triangles.
std::vector<StressCase> order() {
  std::vector<StressCase> out;
  for (double q : {0.0, 1.0}) {
    const Triangle a = tri(vtx(120.5, 80.25, 3000, 250, 40, 40), vtx(700.75, 210.5, 9000, 40, 250, 40),
                           vtx(300.125, 800.5, 5000, 40, 40, 250));
    const Triangle b = tri(vtx(400, 300, 1000, 255, 255, 0, 0.5), vtx(900, 320, 1000, 0, 255, 255, 0.3),
                           vtx(500, 700, 1000, 255, 0, 255, 0.8));
    std::vector<std::string> variants;
    std::array<int, 3> p{0, 1, 2};
    do {
      auto permuted = [&](const Triangle& t) { return tri(t.v[p[0]], t.v[p[1]], t.v[p[2]]); };
      variants.push_back(triangle_trace({permuted(a), permuted(b)}, q, "vertex order " + std::to_string(p[0]) +
                                                                           std::to_string(p[1]) + std::to_string(p[2])));
    } while (std::next_permutation(p.begin(), p.end()));
    StressCase c{"order", "order_q" + label(q), "two triangles in all 6 vertex orders (both windings), Q " + label(q),
                 true, false, variants.front(), {variants.begin() + 1, variants.end()}};
    out.push_back(c);
  }
  return out;
}

// Triangles of one transparent surface sharing edges, edge flags set as
// the front end sets them.
std::vector<Triangle> flagged(std::vector<Triangle> tris) {
  mark_interior_edges(tris);
  return tris;
}

std::vector<StressCase> shared() {
  std::vector<StressCase> out;
  for (double q : {0.0, 1.0}) {
    std::vector<Triangle> fan, grid;
    const double cx = 512, cy = 512, r = 300;
    for (int k = 0; k < 64; ++k) {
      const double a0 = 2 * kPi * k / 64, a1 = 2 * kPi * (k + 1) / 64;
      fan.push_back(tri(vtx(cx, cy, 1000, 200, 100, 50, 0.5),
                        vtx(cx + std::round(r * std::cos(a0)), cy + std::round(r * std::sin(a0)), 1000, 200, 100, 50, 0.5),
                        vtx(cx + std::round(r * std::cos(a1)), cy + std::round(r * std::sin(a1)), 1000, 200, 100, 50, 0.5),
                        0));
    }
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) {
        const double x = 100 + 97.5 * i, y = 110 + 96.25 * j, s0 = 97.5, s1 = 96.25;
        const Vertex a = vtx(x, y, 2000, 50, 200, 250, 0.4), b = vtx(x + s0, y, 2000, 50, 200, 250, 0.4),
                     c = vtx(x + s0, y + s1, 2000, 50, 200, 250, 0.4), d = vtx(x, y + s1, 2000, 50, 200, 250, 0.4);
        grid.push_back(tri(a, b, c, 0));
        grid.push_back(tri(a, c, d, 0));
      }
    out.push_back(trace_case("shared", "fan64_q" + label(q), "a fan of 64 transparent triangles, Q " + label(q), true,
                             flagged(fan), q));
    out.push_back(trace_case("shared", "grid8_q" + label(q), "an 8 x 8 grid of transparent quads (128 triangles), Q " + label(q),
                             q == 0, flagged(grid), q));
  }
  return out;
}

// Scenes through the front end: the camera inside a cube, on its face, and
// low over a floor (the near-plane clip makes huge triangles).
std::vector<StressCase> nearplane(const std::string& models_dir) {
  auto scene = [&](const std::string& eye, const std::string& target, const std::string& models) {
    return "{\"girtd_scene\": 1, \"q\": 1, \"camera\": {\"eye\": " + eye + ", \"target\": " + target +
           ", \"fov_deg\": 60},\n \"materials\": {\"m\": {\"colour\": [200, 180, 120]}, \"glass\": {\"colour\": "
           "[180, 220, 255], \"t_min\": 0.3, \"t_max\": 0.7}},\n \"models\": [" +
           models + "]}\n";
  };
  const std::string cube = "{\"name\": \"cube\", \"file\": \"" + models_dir + "/cube.obj\", \"material\": \"glass\", \"scale\": 2}";
  const std::string floor = "{\"name\": \"floor\", \"file\": \"" + models_dir + "/floor.obj\", \"material\": \"m\", \"scale\": 50}";
  return {{"nearplane", "nearplane_inside_cube", "camera inside a transparent cube", true, true,
           scene("[0.1, 0.2, 0.3]", "[0.0, 0.0, -5.0]", cube), {}},
          {"nearplane", "nearplane_on_face", "camera on a face of the cube", false, true,
           scene("[0.3, 0.1, 1.0]", "[0.0, 0.0, -5.0]", cube), {}},
          {"nearplane", "nearplane_low_floor", "camera 0.01 above a floor 50 units wide", true, true,
           scene("[0.0, 0.01, 0.0]", "[0.0, 0.0, -10.0]", floor), {}}};
}

// Colours and T at 0 and 1, Q at 0 and 8.
std::vector<StressCase> limits() {
  std::vector<StressCase> out;
  for (double q : {0.0, 8.0}) {
    const std::vector<Triangle> tris = {
        tri(vtx(50, 50, 100, 0, 0, 0, 1), vtx(500, 60, 100, 255, 255, 255, 1), vtx(80, 480, 100, 255, 0, 255, 1)),
        tri(vtx(550, 50, 100, 255, 255, 255, 0), vtx(1000, 60, 100, 255, 255, 255, 1), vtx(580, 480, 100, 255, 255, 255, 0)),
        tri(vtx(50, 550, 100, 0, 0, 0, 0), vtx(500, 560, 100, 0, 0, 0, 0), vtx(80, 980, 100, 0, 0, 0, 0)),
        tri(vtx(550, 550, 100, 255, 255, 255, 1), vtx(1000, 560, 100, 255, 255, 255, 1),
            vtx(580, 980, 100, 255, 255, 255, 1))};
    out.push_back(trace_case("limits", "q" + label(q), "colours and T at 0 and 1, Q " + label(q), true, tris, q));
  }
  return out;
}

// Fine meshes: thousands of needle and sub-pixel triangles whose colour and
// depth swing over their whole range across a fraction of a pixel (what a
// scanner's or a CAD export's finely tessellated model gives near its poles
// and silhouettes).
std::vector<StressCase> fine() {
  std::vector<StressCase> out;
  for (double q : {0.0, 1.0}) {
    // A fan of 3,000 needles round (512, 512), 200 px long: 0.42 px wide at the rim.
    std::vector<Triangle> fan;
    const int n = 3000;
    for (int k = 0; k < n; ++k) {
      const double a0 = 2 * kPi * k / n, a1 = 2 * kPi * (k + 1) / n, c = k % 2 ? 255 : 0, z = k % 2 ? 65534 : 0;
      fan.push_back(tri(vtx(512, 512, 32767, 128, 128, 128), vtx(512 + 200 * std::cos(a0), 512 + 200 * std::sin(a0), z, c, 255 - c, c),
                        vtx(512 + 200 * std::cos(a1), 512 + 200 * std::sin(a1), 65534 - z, 255 - c, c, 255 - c)));
    }
    // A 64 x 64 grid of 0.4-px cells (8,192 sub-pixel triangles), every
    // corner's colour and depth drawn from the whole range.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> colour(0, 255), depth(0, 65534);
    std::vector<Vertex> corner;
    for (int j = 0; j <= 64; ++j)
      for (int i = 0; i <= 64; ++i)
        corner.push_back(vtx(300.3 + 0.4 * i, 400.7 + 0.4 * j, depth(rng), colour(rng), colour(rng), colour(rng)));
    std::vector<Triangle> grid;
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i) {
        const Vertex &a = corner[j * 65 + i], &b = corner[j * 65 + i + 1], &c = corner[(j + 1) * 65 + i + 1],
                     &d = corner[(j + 1) * 65 + i];
        grid.push_back(tri(a, b, c));
        grid.push_back(tri(a, c, d));
      }
    out.push_back(trace_case("fine", "fan3000_q" + label(q),
                             "a fan of 3,000 needles 200 px long, colour 0..255 and Z 0..65534 across each, Q " + label(q),
                             q == 1, fan, q));
    out.push_back(trace_case("fine", "grid64_q" + label(q),
                             "a 64 x 64 grid of 0.4-px cells, every corner's colour and Z drawn from the whole range, Q " +
                                 label(q),
                             q == 0, grid, q));
  }
  // A UV sphere of 100 rings (19,800 triangles) through the front end,
  // framed to fill the screen: needles at the poles, one on the silhouette.
  std::string vertices = "[0, 1, 0]", polygons;
  const int rings = 100;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * rings + j % rings; };
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < rings; ++j) {
      const double th = kPi * i / rings, ph = 2 * kPi * j / rings;
      vertices += ", [" + number(std::sin(th) * std::cos(ph)) + ", " + number(std::cos(th)) + ", " +
                  number(std::sin(th) * std::sin(ph)) + "]";
    }
  vertices += ", [0, -1, 0]";
  const int south = 1 + (rings - 1) * rings;
  auto face = [&](int a, int b, int c) {
    polygons += (polygons.empty() ? "[" : ", [") + std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c) + "]";
  };
  for (int j = 0; j < rings; ++j) {
    face(0, ring(1, j + 1), ring(1, j));
    face(south, ring(rings - 1, j), ring(rings - 1, j + 1));
  }
  for (int i = 1; i < rings - 1; ++i)
    for (int j = 0; j < rings; ++j) {
      face(ring(i, j), ring(i, j + 1), ring(i + 1, j + 1));
      face(ring(i, j), ring(i + 1, j + 1), ring(i + 1, j));
    }
  const std::string sphere = "{\"girtd_scene\": 1, \"q\": 1,\n \"models\": [{\"name\": \"sphere\", \"mesh\": "
                             "{\"vertices\": [" + vertices + "], \"polygons\": [" + polygons + "]}}]}\n";
  out.push_back({"fine", "fine_sphere19800", "a UV sphere of 19,800 triangles filling the screen, through the front end",
                 true, true, sphere, {}});
  return out;
}

}  // namespace

const std::vector<std::string>& stress_families() {
  static const std::vector<std::string> f = {"huge",   "sliver", "degenerate", "subpixel",  "steep", "zrange",
                                             "order",  "shared", "nearplane",  "limits",    "fine"};
  return f;
}

std::vector<StressCase> stress_cases(const std::string& family, const std::string& models_dir) {
  if (family == "huge") return huge();
  if (family == "sliver") return sliver();
  if (family == "degenerate") return degenerate();
  if (family == "subpixel") return subpixel();
  if (family == "steep") return steep();
  if (family == "zrange") return zrange();
  if (family == "order") return order();
  if (family == "shared") return shared();
  if (family == "nearplane") return nearplane(models_dir);
  if (family == "limits") return limits();
  if (family == "fine") return fine();
  throw std::logic_error("no stress family " + family);  // CLI11 admits stress_families() only
}

std::string triangle_trace(const std::vector<Triangle>& tris, double q, const std::string& comment) {
  std::string s = "girtd-trace 1 triangle\n# girtd stress: " + comment + "\nq " + number(q) + "\n";
  for (const Triangle& t : tris) {
    s += "tri";
    for (const Vertex& v : t.v)
      s += "  " + number(v.x) + " " + number(v.y) + " " + number(v.z) + " " + number(v.r) + " " + number(v.g) + " " +
           number(v.b) + " " + number(v.t);
    if (t.surface >= 0) s += "  " + std::to_string(t.interior_edges) + " " + std::to_string(t.surface);
    s += "\n";
  }
  return s;
}

}  // namespace girtd
