#include "backends/prune_plan.hpp"

namespace girtd {

PrunePlan plan_pruning(const Trace& input, const std::string& backend, bool enabled) {
  PrunePlan plan;
  if (!enabled) return plan;
  if (input.level != TraceLevel::kPolygon)
    plan.left_out.push_back({"front end", std::string("the input is a ") + level_name(input.level) +
                                              "-level trace: it enters below the front end"});
  if (input.level == TraceLevel::kPolygon) {
    plan.lighting_out_of_view = true;
    plan.left_out.push_back({"lighting", "the colours of polygons wholly outside the view volume (at Zs <= C, or "
                                         "beyond a side of the window): the depth clip or the window clip drops "
                                         "everything made from them. Their flops are still charged"});
  }
  if ((backend == "golden" || backend == "approx") && input.level != TraceLevel::kThesis) {
    plan.unreachable_wraps = true;
    plan.left_out.push_back({"wrap detector", "the guard-bit registers of triangles whose EP values stay within "
                                              "every format over the pixels the DDA can visit: they cannot wrap "
                                              "(models/dda/dda_datapath.hpp may_wrap)"});
  }
  return plan;
}

FrontEndOptions front_end_options(const Params& params, const PrunePlan& plan) {
  FrontEndOptions o;
  o.cull_objects = params.cull_objects;
  o.cull_back_faces_always = params.cull_back_faces_always;
  o.prune_lighting_out_of_view = plan.lighting_out_of_view;
  return o;
}

}  // namespace girtd
