#include "claims/thesis_losses.hpp"

#include <cmath>
#include <random>
#include <set>

#include "claims/equilateral.hpp"
#include "common/fixed_point.hpp"
#include "thesis/thesis_preparer.hpp"

namespace girtd {
namespace {

// Screen pixels (x right, y down) -> the program's units.
ThesisVertex to_thesis_units(const Vertex& s, double kc) {
  ThesisVertex v = s;
  v.x = s.x / kc - 1.0;
  v.y = 0.75 - s.y / kc;
  v.z = 0.25;
  v.r = s.r / 255.0;
  v.g = s.g / 255.0;
  v.b = s.b / 255.0;
  v.t = 1.0;
  return v;
}

}  // namespace

ThesisLossSample measure_thesis_losses(const Params& base, ThesisInside inside, int count, uint32_t seed) {
  const Params p = base.with_thesis_formats();
  const DdaPix ddapix(p, inside);
  const int64_t threshold = inside == ThesisInside::kProgram ? -(int64_t{1} << 16) : 0;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  ThesisLossSample s;
  for (int n = 0; n < count; ++n) {
    // Log-uniform size from 0.5 to 64 pixels of the 128 x 96 screen.
    const double size = std::exp(std::log(0.5) + u(rng) * std::log(128.0));
    const double cx = u(rng) * p.thesis.width, cy = u(rng) * p.thesis.height;
    std::array<ThesisVertex, 3> v;
    for (ThesisVertex& t : v) {
      Vertex sv;
      sv.x = cx + (u(rng) - 0.5) * size;
      sv.y = cy + (u(rng) - 0.5) * size;
      sv.r = 255 * u(rng);
      t = to_thesis_units(sv, p.thesis.kc);
    }
    const auto d = thesis_prepare(v, p);
    if (!d) continue;
    ++s.triangles;
    std::set<std::pair<int, int>> emitted;
    ddapix.run(*d, [&](const DdaEmit& e) {
      if (e.pixel.x < d->xmin || e.pixel.x > d->xmax) ++s.outside_limit_emits;
      emitted.insert({e.pixel.x, e.pixel.y});
    });
    uint64_t lost = 0;
    for (int y = d->y0; y <= d->ymax; ++y) {
      for (int x = d->xmin; x <= d->xmax; ++x) {
        bool in = true;
        for (int e = kEpD1; e <= kEpD3; ++e) {
          const EpInit& ep = d->ep[e];
          in = in && wrap_to_bits(ep.v + int64_t(x - d->x0) * ep.dx + int64_t(y - d->y0) * ep.dy, 32) >= threshold;
        }
        if (!in) continue;
        ++s.inside_pixels;
        lost += emitted.count({x, y}) == 0;
      }
    }
    s.lost_pixels += lost;
    s.triangles_losing += lost > 0;
  }
  return s;
}

ThesisEfficiency measure_thesis_equilateral(const Params& base, bool apex_up) {
  const Params p = base.with_thesis_formats();
  const DdaPix ddapix(p, ThesisInside::kProgram);
  ThesisEfficiency r;
  int n = 0;
  for_each_subpixel_position(64, 48, [&](double cx, double cy) {
    const Triangle t = equilateral_200(cx, cy, apex_up ? 0 : M_PI);
    std::array<ThesisVertex, 3> v;
    for (int k = 0; k < 3; ++k) v[k] = to_thesis_units(t.v[k], p.thesis.kc);
    const auto d = thesis_prepare(v, p);
    if (!d) return;
    const DdaRunStats st = ddapix.run(*d, {});
    r.mean_emitted += double(st.emitted);
    r.mean_wasted += double(st.wasted());
    r.mean_efficiency += double(st.emitted) / double(st.cycles);
    r.mean_formula += thesis_wasted_states(t);
    ++n;
  });
  if (n > 0) {
    r.mean_emitted /= n;
    r.mean_wasted /= n;
    r.mean_efficiency /= n;
    r.mean_formula /= n;
  }
  return r;
}

}  // namespace girtd
