// The stress verdict on hand-made pictures: a difference nothing counted is a
// FAIL, one on a counted triangle is flagged only when golden and rtl warned
// of it, and golden != rtl is a FAIL whatever the pictures.
#include <catch2/catch.hpp>

#include "stress/stress_judge.hpp"

namespace girtd {
namespace {

RgbImage black() {
  RgbImage img;
  img.width = img.height = 1024;
  img.rgb.assign(size_t(1024) * 1024 * 3, 0);
  return img;
}

void set_red(RgbImage& img, int x, int y, uint8_t v) { img.rgb[(size_t(y) * 1024 + x) * 3] = v; }

Trace one_triangle(const Triangle& t, double q) {
  Trace tr;
  tr.frames.resize(1);
  tr.frames[0].settings.q = q;
  tr.frames[0].triangles = {t};
  return tr;
}

Triangle triangle(double x0, double y0, double x1, double y1, double x2, double y2) {
  Triangle t;
  t.v = {Vertex{x0, y0, 100, 200, 0, 0, 1}, Vertex{x1, y1, 100, 200, 0, 0, 1}, Vertex{x2, y2, 100, 200, 0, 0, 1}};
  return t;
}

nlohmann::json report(const std::string& warning = "") {
  nlohmann::json r = {{"image_sha256", "same"}, {"pixels_generated", 1}, {"pixels_reblended", 0}, {"numerics", nullptr}};
  r["warnings"] = warning.empty() ? nlohmann::json::array() : nlohmann::json::array({warning});
  return r;
}

}  // namespace

TEST_CASE("stress judge: a difference away from every triangle is a silent FAIL", "[stress]") {
  const Params p = Params::defaults();
  const Trace t = one_triangle(triangle(100, 100, 200, 100, 100, 200), 0);
  RgbImage ref = black(), golden = black();
  set_red(golden, 700, 700, 200);  // far from the triangle: no budget, nothing counted
  const StressJudgement j = judge_stress_case(t, p, report(), report(), report(), ref, golden);
  CHECK(j.verdict == StressVerdict::kFail);
  CHECK(j.silent == 1);
  // Within the colour budget (3 LSB for 9 fraction bits over 2048 steps) it is exact.
  RgbImage near = black();
  set_red(near, 700, 700, 3);
  CHECK(judge_stress_case(t, p, report(), report(), report(), ref, near).verdict == StressVerdict::kExact);
  // At an edge (x = 150 on the hypotenuse x + y = 300, y = 150) it is within the edge budget.
  RgbImage edge = black();
  set_red(edge, 150, 150, 200);
  CHECK(judge_stress_case(t, p, report(), report(), report(), ref, edge).verdict == StressVerdict::kExact);
}

TEST_CASE("stress judge: a difference on a counted triangle is flagged only when warned", "[stress]") {
  const Params p = Params::defaults();
  // Corners 1,500 px beyond the screen: golden counts D wraps on it.
  const Trace t = one_triangle(triangle(-1500, -1500, 4100, -1500, -1500, 4100), 0);
  RgbImage ref = black(), golden = black();
  set_red(ref, 500, 900, 200);
  const std::string w = "x: wrapped EP values in use (D1 5)";
  CHECK(judge_stress_case(t, p, report(), report(w), report(w), ref, golden).verdict == StressVerdict::kFlagged);
  CHECK(judge_stress_case(t, p, report(), report(), report(), ref, golden).verdict == StressVerdict::kFail);
  CHECK(judge_stress_case(t, p, report(), report(w), report(), ref, golden).verdict == StressVerdict::kFail);
}

TEST_CASE("stress judge: golden != rtl is a FAIL", "[stress]") {
  const Params p = Params::defaults();
  const Trace t = one_triangle(triangle(100, 100, 200, 100, 100, 200), 0);
  nlohmann::json rtl = report();
  rtl["pixels_generated"] = 2;
  const StressJudgement j = judge_stress_case(t, p, report(), report(), rtl, black(), black());
  CHECK(j.verdict == StressVerdict::kFail);
  CHECK_THAT(j.why, Catch::Contains("pixels_generated"));
}

}  // namespace girtd
