// Hand-worked checks of §3 lighting: vertex normals and the colour formula.
#include <catch2/catch.hpp>

#include <cmath>

#include "frontend/vertex_lighting.hpp"
#include "frontend/vertex_normals.hpp"

using namespace girtd;

namespace {

// Cube [-1,1]^3, faces counter-clockwise from outside.
std::vector<WorldPolygon> cube(bool one_surface) {
  const std::vector<std::vector<Vec3>> faces = {
      {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},      // +x
      {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},  // -x
      {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},      // +y
      {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}},  // -y
      {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},      // +z
      {{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}},  // -z
  };
  std::vector<WorldPolygon> out;
  for (size_t i = 0; i < faces.size(); ++i) out.push_back({one_surface ? 0 : static_cast<int>(i), faces[i], 0});
  return out;
}

}  // namespace

TEST_CASE("cube vertex normals: one surface averages, six surfaces keep face normals", "[frontend]") {
  // Newell normal of the +x face: length 2 x area = 2 x 4 = 8, along +x.
  const Vec3 n = newell_normal(cube(true)[0].p);
  CHECK(n.x == Approx(8));
  CHECK(n.y == Approx(0).margin(1e-9));
  CHECK(n.z == Approx(0).margin(1e-9));

  // One surface: corner (1,1,1) touches +x, +y, +z -> (1,1,1)/sqrt(3) = 0.57735 each.
  const std::vector<WorldPolygon> one_surface = cube(true), six_surfaces = cube(false);
  const auto smooth = vertex_normals(one_surface);
  const Vec3 c = smooth.at(0, 2);  // +x face, vertex (1,1,1)
  CHECK(c.x == Approx(1 / std::sqrt(3.0)));
  CHECK(c.y == Approx(1 / std::sqrt(3.0)));
  CHECK(c.z == Approx(1 / std::sqrt(3.0)));
  // Corner (-1,-1,-1) on the -y face: (-1,-1,-1)/sqrt(3).
  CHECK(smooth.at(3, 0).x == Approx(-1 / std::sqrt(3.0)));

  // Six surfaces: the same corner keeps three different normals, one per surface.
  const auto flat = vertex_normals(six_surfaces);
  CHECK(flat.at(0, 2).x == Approx(1));
  CHECK(flat.at(0, 2).y == Approx(0).margin(1e-9));
  CHECK(flat.at(2, 2).y == Approx(1));  // +y face, vertex (1,1,1)
  CHECK(flat.at(4, 2).z == Approx(1));  // +z face, vertex (1,1,1)
}

TEST_CASE("lighting: light straight on and at 60 degrees, CRE interpolation", "[frontend]") {
  Surface s;
  s.r = 200, s.g = 100, s.b = 0;
  s.cre = {0.5, 0.4, 0.3, 0.2, 0.1, 0.07, 0.01};  // 75 and 90 deg distinct, not in line with 60: the last interval is checked too
  s.n = 10;
  LightSet l;
  l.ambient = 0.2;
  const Vec3 n{0, 0, 1};

  // Straight on, eye straight on: N.I = 1, R = 2(1)N - I = N, R.E = 1, i = 0 -> CRE 0.5.
  // r = 200 x 0.2 + 200 x 0.5 x 1 + 255 x 0.5 x 1 x 0.5 = 40 + 100 + 63.75 = 203.75
  // g = 100 x 0.7 + 63.75 = 133.75; b = 63.75
  l.directional = {{{0, 0, 1}, 0.5}};
  LitVertex v = light_vertex(s, l, n, {0, 0, 1});
  CHECK(v.r == Approx(203.75));
  CHECK(v.g == Approx(133.75));
  CHECK(v.b == Approx(63.75));
  CHECK(v.t == 1);

  // Light at 60 deg: I = (sin 60, 0, cos 60), N.I = 0.5. R = 2 x 0.5 x N - I = (-0.866, 0, 0.5).
  // Eye along R: R.E = 1; i = 60 -> CRE(60) = 0.1.
  // r = 200 x 0.2 + 200 x 0.5 x 0.5 + 255 x 0.1 x 1 x 0.5 = 40 + 50 + 12.75 = 102.75
  const double s60 = std::sqrt(3.0) / 2;
  l.directional = {{{s60, 0, 0.5}, 0.5}};
  v = light_vertex(s, l, n, {-s60, 0, 0.5});
  CHECK(v.r == Approx(102.75));
  // Eye straight on instead: R.E = 0.5, 0.5^10 = 1/1024: specular 255 x 0.1 x 0.5/1024 = 0.01245.
  v = light_vertex(s, l, n, {0, 0, 1});
  CHECK(v.r == Approx(90 + 255 * 0.1 * 0.5 / 1024));

  // CRE halfway between samples: 37.5 deg -> (0.3 + 0.2) / 2 = 0.25; beyond 90 clamps.
  CHECK(cre_at(s, 37.5) == Approx(0.25));
  CHECK(cre_at(s, 90) == Approx(0.01));
  CHECK(cre_at(s, 75) == Approx(0.07));
  CHECK(cre_at(s, 82.5) == Approx(0.04));
  CHECK(cre_at(s, 120) == Approx(0.01));
  CHECK(cre_at(s, 7.5) == Approx(0.45));

  // Light behind the surface: N.I < 0 clamps to 0, only ambient remains: 200 x 0.2 = 40.
  l.directional = {{{0, 0, -1}, 0.5}};
  CHECK(light_vertex(s, l, n, {0, 0, 1}).r == Approx(40));

  // Saturation: ambient 2 -> 400 -> 255.
  l.ambient = 2;
  CHECK(light_vertex(s, l, n, {0, 0, 1}).r == 255);
}

TEST_CASE("lighting: transparency Tf = Tmin + (Tmax - Tmin)|N.E|, T = 1 - Tf", "[frontend]") {
  Surface s;
  s.t_min = 0.2, s.t_max = 0.8;
  LightSet l;
  const Vec3 n{0, 0, 1};
  // Face on: |N.E| = 1 -> Tf = 0.8, T = 0.2.
  CHECK(light_vertex(s, l, n, {0, 0, 1}).t == Approx(0.2));
  // At 60 deg: |N.E| = 0.5 -> Tf = 0.2 + 0.6 x 0.5 = 0.5, T = 0.5.
  CHECK(light_vertex(s, l, n, {std::sqrt(3.0) / 2, 0, 0.5}).t == Approx(0.5));
  // Seen from behind: |N.E| still 1.
  CHECK(light_vertex(s, l, n, {0, 0, -1}).t == Approx(0.2));
}
