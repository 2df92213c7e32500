// Simulator pruning: what a render may leave uncomputed because nothing it
// outputs depends on it (render --no-prune turns it off). Decided here, from
// the input, for every unit at once; the units only read their flag, and
// count what they skipped. Nothing here changes the modeled hardware: every
// count, modeled tick and pixel equals the unpruned run's (CTest "cli:
// pruning changes nothing but wall time"); what was skipped is report.json's
// `left_out`.
#pragma once

#include <string>
#include <vector>

#include "backends/run_stats.hpp"
#include "io/trace.hpp"

namespace girtd {

struct PrunePlan {
  // Front end: polygons wholly outside the view volume are not lit (the
  // depth clip or the window clip drops everything made from them).
  bool lighting_out_of_view = false;
  // DDA (the golden engine, on golden and approx): no wrap-detector
  // registers for triangles whose EP values provably stay within their
  // formats (models/dda may_wrap). rtl's detector is hardware: it always runs.
  bool unreachable_wraps = false;
  // DDA (the same engine): such a triangle's emitting runs computed as
  // whole spans, not clock by clock (models/dda/dda_span.hpp).
  bool dda_spans = false;
};

// `enabled`: false for --no-prune (nothing is skipped).
PrunePlan plan_pruning(TraceLevel input, bool enabled);

struct LeftOut {
  std::string unit;
  std::string reason;
};

// What the run skipped, from what the units counted: one entry per unit
// that skipped anything (report.json `left_out`).
std::vector<LeftOut> left_out(const RunStats& stats);

}  // namespace girtd
