// Builders shared by the DDA tests: parameter sets from integer edge
// functions, so hand-traced examples read like the arithmetic in comments.
#pragma once

#include <set>
#include <utility>
#include <vector>

#include "config/params.hpp"
#include "dda/dda_engine.hpp"

namespace girtd::test {

// Edge function D = a x + b y + c in pixel units.
struct Lin {
  double a, b, c;
};

// A parameter set whose three D EPs hold the given edge functions exactly,
// colours constant (R = 100, G = 150, B = 200), opaque, Z = 1000.
inline DdaParams make_params(const Params& p, int x0, int y0, int xmin, int xmax, int ymax, Lin d1, Lin d2, Lin d3,
                             double q = 0) {
  DdaParams d;
  d.x0 = x0;
  d.y0 = y0;
  d.xmin = xmin;
  d.xmax = xmax;
  d.ymax = ymax;
  d.q = q;
  const double one_d = double(p.ep_d.one());
  const Lin lins[3] = {d1, d2, d3};
  for (int i = 0; i < 3; ++i) {
    const Lin& l = lins[i];
    d.ep[kEpD1 + i] = {static_cast<int64_t>((l.a * x0 + l.b * y0 + l.c) * one_d), static_cast<int64_t>(l.a * one_d),
                       static_cast<int64_t>(l.b * one_d)};
  }
  d.ep[kEpR].v = 100 * p.ep_color.one();
  d.ep[kEpG].v = 150 * p.ep_color.one();
  d.ep[kEpB].v = 200 * p.ep_color.one();
  d.ep[kEpT].v = 256 * p.ep_t.one();
  d.ep[kEpZ].v = 1000 * p.ep_z.one();
  return d;
}

struct Trace {
  std::vector<DdaClock> clocks;
  std::vector<std::pair<int, int>> pixels;
  DdaRunStats stats;
};

inline Trace run_traced(const Params& p, const DdaParams& d) {
  Trace t;
  DdaEngine e(p);
  t.stats = e.run(d, [&](const DdaEmit& em) { t.pixels.emplace_back(em.pixel.x, em.pixel.y); },
                  [&](const DdaClock& c) { t.clocks.push_back(c); });
  return t;
}

inline Params ecl_params() {
  Params p = Params::defaults();
  p.xy_compare_pipelined = false;
  p.walk_fix = true;
  return p;
}

}  // namespace girtd::test
