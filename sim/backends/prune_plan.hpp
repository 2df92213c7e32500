// Simulator pruning: what a render may leave uncomputed because nothing it
// outputs depends on it (render --no-prune turns it off). Decided here, from
// the input and the configuration, for every unit at once; the units only
// read their flag. Nothing here changes the modeled hardware: every count,
// modeled tick and pixel equals the unpruned run's (CTest "cli: pruning
// changes nothing but wall time"); what was skipped is report.json's
// `left_out`.
#pragma once

#include <string>
#include <vector>

#include "config/params.hpp"
#include "frontend/front_end_stages.hpp"
#include "io/trace.hpp"

namespace girtd {

struct LeftOut {
  std::string unit;
  std::string reason;
};

struct PrunePlan {
  // Front end: polygons wholly outside the view volume are not lit (the
  // depth clip or the window clip drops everything made from them).
  bool lighting_out_of_view = false;
  // DDA (golden, approx): no wrap-detector registers for triangles whose EP
  // values provably stay within their formats (models/dda may_wrap). rtl's
  // detector is hardware: it always runs.
  bool unreachable_wraps = false;
  std::vector<LeftOut> left_out;  // report.json `left_out`, one entry per unit skipped
};

// `backend`: the --backend name; `enabled`: false for --no-prune (nothing is
// skipped that can be computed).
PrunePlan plan_pruning(const Trace& input, const std::string& backend, bool enabled);

// The front end's options: the configuration's culling and the plan's pruning.
FrontEndOptions front_end_options(const Params& params, const PrunePlan& plan);

}  // namespace girtd
