#include "claims/ep_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

#include "common/fixed_point.hpp"
#include "common/triangle_setup.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"

namespace girtd {

EpErrorSample measure_ep_error(const Params& p, int triangles, double span, int max_steps, uint32_t seed) {
  DdaPreparer prep(p);
  DdaEngine dda(p);
  FrameSettings f;
  f.q = 1;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(0, span), colour(0, (1 << p.ep_color.out_bits) - 1),
      depth(0, p.depth_max_mapped), opacity(0, 1);
  EpErrorSample s;
  for (int n = 0; n < triangles; ++n) {
    Triangle t;
    for (Vertex& v : t.v) {
      v.x = coord(rng);
      v.y = coord(rng);
      v.z = depth(rng);
      v.r = colour(rng);
      v.g = colour(rng);
      v.b = colour(rng);
      v.t = opacity(rng);
    }
    DdaParams dp;
    if (prep.prepare(t, f, dp) != PrepareResult::kReady) continue;
    const TriangleSetup setup = *setup_triangle(t);
    dda.run(dp, [&](const DdaEmit& e) {
      const int steps = std::abs(e.pixel.x - dp.x0) + std::abs(e.pixel.y - dp.y0);
      if (steps > max_steps) return;
      const double x = e.pixel.x, y = e.pixel.y;
      for (int a : {kR, kG, kB})
        s.max_color_lsb = std::max(s.max_color_lsb,
                                   std::fabs(to_double(e.raw[kEpR + a], p.ep_color) - setup.attr[a].at(x, y)));
      s.max_z_lsb = std::max(s.max_z_lsb, std::fabs(to_double(e.raw[kEpZ], p.ep_z) - setup.attr[kZ].at(x, y)));
      s.max_t_lsb = std::max(s.max_t_lsb, std::fabs(to_double(e.raw[kEpT], p.ep_t) - 256 * setup.attr[kT].at(x, y)));
      for (int i = 0; i < 3; ++i)
        s.max_d_px = std::max(s.max_d_px, std::fabs(to_double(e.raw[kEpD1 + i], p.ep_d) - setup.edge[i].at(x, y)));
      s.max_steps = std::max(s.max_steps, steps);
      ++s.pixels;
    });
  }
  return s;
}

}  // namespace girtd
