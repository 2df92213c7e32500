#include "claims/ep_precision.hpp"

#include <cmath>
#include <cstdlib>
#include <random>

#include "common/fixed_point.hpp"
#include "common/triangle_setup.hpp"
#include "dda/dda_preparer.hpp"

namespace girtd {

const char* ep_key(EpKind ep) {
  switch (ep) {
    case EpKind::kColor: return "color";
    case EpKind::kT: return "t";
    case EpKind::kZ: return "z";
    case EpKind::kD: return "d";
  }
  return "";
}

FixFormat& ep_format(Params& p, EpKind ep) {
  switch (ep) {
    case EpKind::kColor: return p.ep_color;
    case EpKind::kT: return p.ep_t;
    case EpKind::kZ: return p.ep_z;
    case EpKind::kD: break;
  }
  return p.ep_d;
}

double ep_budget(EpKind ep) { return ep == EpKind::kD ? 0.125 : 1.0; }
double ep_bound(EpKind ep, int frac_bits) { return ep_budget(ep) + std::ldexp(1.0, -frac_bits - 1); }
const char* ep_unit(EpKind ep) { return ep == EpKind::kD ? "px" : "LSB"; }

double ep_error_after_steps(const Params& p, EpKind ep, int steps, int triangles, uint32_t seed) {
  DdaPreparer prep(p);
  FrameSettings f;
  f.q = 1;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(0, p.screen_width - 1), colour(0, (1 << p.ep_color.out_bits) - 1),
      depth(0, p.depth_max_mapped), opacity(0, 1);
  Params formats = p;
  const FixFormat& fmt = ep_format(formats, ep);
  double worst = 0;
  for (int n = 0; n < triangles; ++n) {
    Triangle t;
    for (Vertex& v : t.v) v = Vertex{coord(rng), coord(rng), depth(rng), colour(rng), colour(rng), colour(rng), opacity(rng)};
    DdaParams dp;
    if (prep.prepare(t, f, dp) != PrepareResult::kReady) continue;
    const TriangleSetup s = *setup_triangle(t);
    for (const auto& [i, j] : {std::pair{steps, 0}, {-steps, 0}, {0, steps}, {0, -steps}}) {
      const double x = dp.x0 + i, y = dp.y0 + j;
      auto after = [&](const EpInit& e) { return to_double(e.v + i * e.dx + j * e.dy, fmt); };
      switch (ep) {
        case EpKind::kColor:
          for (int a : {kR, kG, kB}) worst = std::max(worst, std::fabs(after(dp.ep[kEpR + a]) - s.attr[a].at(x, y)));
          break;
        case EpKind::kT: worst = std::max(worst, std::fabs(after(dp.ep[kEpT]) - 256 * s.attr[kT].at(x, y))); break;
        case EpKind::kZ: worst = std::max(worst, std::fabs(after(dp.ep[kEpZ]) - s.attr[kZ].at(x, y))); break;
        case EpKind::kD:
          for (int e = 0; e < 3; ++e) worst = std::max(worst, std::fabs(after(dp.ep[kEpD1 + e]) - s.edge[e].at(x, y)));
          break;
      }
    }
  }
  return worst;
}

EpPrecision ep_precision(const Params& p, EpKind ep) {
  EpPrecision r;
  r.ep = ep;
  Params q = p;
  r.configured = ep_format(q, ep).frac_bits;
  for (int bits = ep == EpKind::kD ? p.norm_frac_bits : 1; bits <= r.configured + 8; ++bits) {
    ep_format(q, ep).frac_bits = bits;
    const double e1 = ep_error_after_steps(q, ep, kAcrossSteps), e2 = ep_error_after_steps(q, ep, kCornerSteps);
    if (r.fewest_across < 0 && e1 <= ep_bound(ep, bits)) r.fewest_across = bits;
    if (r.fewest_corner < 0 && e2 <= ep_bound(ep, bits)) r.fewest_corner = bits;
    if (bits == r.configured) r.error_across = e1, r.error_corner = e2;
    if (r.fewest_corner >= 0 && bits >= r.configured) break;
  }
  return r;
}

}  // namespace girtd
