#include "claims/numeric_limits.hpp"

#include <algorithm>
#include <cmath>

#include "common/triangle_setup.hpp"
#include "girtd/design_constants.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"

namespace girtd {

bool overhang_drawn_right(const Params& p, double overhang) {
  // Corners (-o, -o), (2 (W - 1) + 2o, -o), (-o, 2 (W - 1) + 2o), W the
  // screen's width: the long edge passes W - 1 + o px beyond its far corner.
  const double lo = -overhang, hi = 2 * (kScreenWidth - 1) + 2 * overhang;
  Triangle t;
  t.v = {Vertex{lo, lo, 30000, 200, 100, 50, 1}, Vertex{hi, lo, 30000, 200, 100, 50, 1},
         Vertex{lo, hi, 30000, 200, 100, 50, 1}};
  FrameSettings f;
  f.q = 0;
  DdaPreparer prep(p);
  DdaParams d;
  if (prep.prepare(t, f, d) != PrepareResult::kReady || d.clamped) return false;
  const DdaRunStats s = DdaEngine(p).run(d, nullptr);
  return s.emitted == 1048576 && s.numerics.wraps() == 0;
}

double largest_safe_overhang(const Params& p) {
  if (overhang_drawn_right(p, kLargestOverhang)) return kLargestOverhang;
  double good = 0, bad = kLargestOverhang;
  if (!overhang_drawn_right(p, good)) return -1;
  while (bad - good > 1) {
    const double mid = std::floor((good + bad) / 2);
    (overhang_drawn_right(p, mid) ? good : bad) = mid;
  }
  return good;
}

CollapseSample measure_collapse(const Params& p, double area) {
  DdaPreparer prep(p);
  const DdaEngine dda(p);
  FrameSettings f;
  f.q = 1;
  CollapseSample s;
  for (int k = 0; k < 20; ++k) {
    const double x = 100 + 37.3 * k, y = 100.25 + 40 * k, base = 200, height = 2 * area / base;
    Triangle t;
    t.v = {Vertex{x, y, 1000, 0, 0, 0, 1}, Vertex{x + base, y, 1000, 0, 0, 0, 1},
           Vertex{x + base / 3, y + height, 1000, 255, 0, 0, 1}};
    ++s.triangles;
    DdaParams d;
    if (prep.prepare(t, f, d) != PrepareResult::kReady) {
      ++s.dropped;
      continue;
    }
    const TriangleSetup setup = *setup_triangle(t);
    dda.run(d, [&](const DdaEmit& e) {
      ++s.pixels;
      const double ideal = std::floor(std::clamp(setup.attr[kR].at(e.pixel.x, e.pixel.y), 0.0, 255.0));
      s.max_colour_error = std::max(s.max_colour_error, static_cast<int>(std::fabs(e.pixel.r - ideal)));
    });
  }
  s.clamped_values = prep.counts().clamped_values();
  return s;
}

}  // namespace girtd
