#include "backends/prune_plan.hpp"

namespace girtd {

PrunePlan plan_pruning(TraceLevel input, bool enabled) {
  PrunePlan plan;
  if (!enabled) return plan;
  plan.lighting_out_of_view = input == TraceLevel::kPolygon;
  plan.unreachable_wraps = true;
  plan.dda_spans = true;
  return plan;
}

std::vector<LeftOut> left_out(const RunStats& s) {
  std::vector<LeftOut> out;
  if (s.frontend && s.frontend->unlit > 0)
    out.push_back({"lighting", std::to_string(s.frontend->unlit) +
                                   " polygons wholly outside the view volume (at Zs <= C, or beyond a side of the "
                                   "window) were not lit: the depth clip or the window clip drops everything made "
                                   "from them (the timed back ends still charge their lighting flops)"});
  if (s.dda && s.dda->undetected > 0)
    out.push_back({"wrap detector", std::to_string(s.dda->undetected) + " of " + std::to_string(s.dda->triangles) +
                                        " triangles ran without the wrap detector's registers: their EP values stay "
                                        "within every format over the pixels the DDA can visit, so they cannot wrap "
                                        "(models/dda/dda_datapath.hpp may_wrap)"});
  if (s.dda && s.dda->span_clocks > 0)
    out.push_back({"DDA clocks", std::to_string(s.dda->span_clocks) + " of " + std::to_string(s.dda->cycles) +
                                     " DDA clocks were taken on the span path, not one loop iteration each: in a "
                                     "triangle that cannot wrap, a run's registers are linear in X, so its length "
                                     "and clipped outputs follow from its ends; the clocks that find and end the "
                                     "run, and the one-clock states after it, are counted with it "
                                     "(models/dda/dda_span.hpp)"});
  return out;
}

}  // namespace girtd
