// The verdict on one `girtd stress` case (docs/interface.md):
//   exact    golden == rtl (picture, counts, numerics) and golden within the
//            thesis' budget of the reference (below), no seams;
//   flagged  every difference beyond the budget lies on pixels a triangle
//            the run counted (a wrap or a clamp in `numerics`) draws in
//            golden or covers in the reference, and
//            golden and rtl warned of it; or the run counted seams
//            (`pixels_reblended`) and warned of them;
//   FAIL     a silent difference, golden != rtl, a crash or a hang.
// The budget, from the formats (the thesis' 1 LSB and 0.125 px per 1024
// steps, stretched to the longest walk, width + height = 2,048 steps on
// the 1024 x 1024 screen: 0.25 px, and 1 LSB of
// truncation plus 2 of the colour EP's error): a pixel is excused when it
// lies within the D error of an edge or in a fringe (whose colour moves with
// the edge), or where two triangles' depths are within the Z error;
// elsewhere each channel may differ by the colour error.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/params.hpp"
#include "io/png_io.hpp"
#include "io/trace.hpp"

namespace girtd {

enum class StressVerdict { kExact, kFlagged, kFail };
const char* verdict_name(StressVerdict v);

struct StressJudgement {
  StressVerdict verdict = StressVerdict::kExact;
  std::string why;                 // empty for exact
  uint64_t beyond_budget = 0;      // pixels off the reference beyond the budget
  uint64_t silent = 0;             // ... of them on triangles nothing counted
  uint64_t affected_triangles = 0;  // with a wrap or a clamp (golden, in-process)
};

struct StressBudget {
  double edge_px;   // D error: pixels this close to an edge are excused
  int colour_lsb;   // per channel elsewhere
  double z_units;   // depths this close let either triangle win
  static StressBudget of(const Params& p);
};

// `triangles`: the case as drawn (a triangle trace: the case itself, or the
// front end's dump of a scene); `reports`: reference, golden, rtl;
// `reference`, `golden`: their frames.
StressJudgement judge_stress_case(const Trace& triangles, const Params& p, const nlohmann::json& reference_report,
                                  const nlohmann::json& golden_report, const nlohmann::json& rtl_report,
                                  const RgbImage& reference, const RgbImage& golden);

}  // namespace girtd
