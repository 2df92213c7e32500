#include "claims/dda_efficiency.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "claims/equilateral.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"

namespace girtd {

const char* orientation_name(Orientation o) {
  switch (o) {
    case Orientation::kApexUp: return "apex up";
    case Orientation::kApexDown: return "apex down";
    default: return "random rotation";
  }
}

EfficiencySample measure_equilateral(const Params& base, Orientation o, double q, bool pipelined) {
  Params p = base;
  p.xy_compare_pipelined = pipelined;
  DdaPreparer prep(p);
  DdaEngine dda(p);
  FrameSettings f;
  f.q = q;
  std::mt19937 rng(1988);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);

  EfficiencySample s;
  s.min_wasted = s.min_efficiency = 1e300;
  for_each_subpixel_position(512, 512, [&](double cx, double cy) {
    const double a = o == Orientation::kApexUp ? 0 : o == Orientation::kApexDown ? M_PI : angle(rng);
    const Triangle t = equilateral_200(cx, cy, a);
    DdaParams dp;
    if (prep.prepare(t, f, dp) != PrepareResult::kReady) return;
    const DdaRunStats r = dda.run(dp, {});
    const double eff = double(r.emitted) / double(r.cycles);
    s.mean_emitted += double(r.emitted);
    s.mean_wasted += double(r.wasted());
    s.min_wasted = std::min(s.min_wasted, double(r.wasted()));
    s.max_wasted = std::max(s.max_wasted, double(r.wasted()));
    s.mean_efficiency += eff;
    s.min_efficiency = std::min(s.min_efficiency, eff);
    s.max_efficiency = std::max(s.max_efficiency, eff);
    s.mean_thesis_wasted += thesis_wasted_states(t);
    ++s.triangles;
  });
  const double n = std::max(1, s.triangles);
  s.mean_emitted /= n;
  s.mean_wasted /= n;
  s.mean_efficiency /= n;
  s.mean_thesis_wasted /= n;
  return s;
}

}  // namespace girtd
