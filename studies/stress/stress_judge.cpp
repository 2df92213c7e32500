#include "stress/stress_judge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "common/triangle_setup.hpp"
#include "girtd/design_constants.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"
#include "reference/reference_rasterizer.hpp"

namespace girtd {
namespace {

constexpr double kLongestWalk = kScreenWidth + kScreenHeight;  // steps: across and down the screen

// Per pixel of the screen: how the budget treats it.
struct Zones {
  int width = 0;
  std::vector<uint8_t> edge;      // within the D error of an edge, or in a fringe
  std::vector<uint8_t> affected;  // drawn (golden) or covered (reference) by a triangle the run counted
  std::vector<uint8_t> near;      // near triangles so far (z conflicts)
  std::vector<float> z;           // the reference depth of the last near triangle
  std::vector<uint8_t> z_conflict;
};

// Marks the lattice points within the budget of triangle `t` (its edge
// distances as the configured rules measure them).
void mark_triangle(const Triangle& t, const FrameSettings& f, const Params& p, const StressBudget& b, Zones& z) {
  const auto setup = setup_triangle(t);
  if (!setup) return;
  const TriangleSetup& s = *setup;
  const double reach = f.q + b.edge_px;
  const PixelBox box = fringe_box(s, reach, f.window);
  const RuleEdges edges(s, f, EdgeRules{p.fill_top_left, p.edge_flags});
  for (int y = box.y0; y <= box.y1; ++y)
    for (int x = box.x0; x <= box.x1; ++x) {
      bool near = true, at_edge = false;
      for (int i = 0; i < 3; ++i) {
        const double d = edges.distance(i, x, y);
        near = near && d >= -edges.q(i) - b.edge_px;
        at_edge = at_edge || d <= b.edge_px;
      }
      if (!near) continue;
      const size_t k = static_cast<size_t>(y) * z.width + x;
      z.edge[k] |= at_edge;
      const double depth = s.attr[kZ].at(x, y);
      if (z.near[k] && std::fabs(depth - z.z[k]) <= b.z_units) z.z_conflict[k] = 1;
      z.near[k] = 1;
      z.z[k] = static_cast<float>(depth);
    }
}

// The triangles the run counted, as golden's preparer and DDA count them;
// marks the pixels each draws (golden) or covers (the reference) in `z.affected`.
std::vector<bool> counted_triangles(const TraceFrame& frame, const Params& p, Zones& z) {
  DdaPreparer preparer(p);
  const DdaEngine engine(p);
  const EdgeRules rules{p.fill_top_left, p.edge_flags};
  std::vector<bool> out;
  DdaParams d;
  auto mark = [&](int x, int y) {
    if (x >= 0 && y >= 0 && x < z.width && y < static_cast<int>(z.affected.size()) / z.width)
      z.affected[static_cast<size_t>(y) * z.width + x] = 1;
  };
  for (const Triangle& t : frame.triangles) {
    bool hit = false;
    std::vector<std::pair<int, int>> drawn;
    if (preparer.prepare(t, frame.settings, d) == PrepareResult::kReady)
      hit = engine.run(d, [&](const DdaEmit& e) { drawn.push_back({e.pixel.x, e.pixel.y}); })
                .numerics.triangles_affected > 0;
    if (hit) {
      for (const auto& [x, y] : drawn) mark(x, y);
      rasterize_reference(t, frame.settings, rules, [&](const ReferenceSample& s) { mark(s.x, s.y); });
    }
    out.push_back(hit);
  }
  return out;
}

std::string first_difference(const nlohmann::json& g, const nlohmann::json& r) {
  for (const char* k : {"image_sha256", "triangles_in", "triangles_drawn", "pixels_generated", "pixels_written",
                        "pixels_blended", "pixels_z_rejected", "pixels_dropped", "dda_cycles", "numerics"})
    if (g.value(k, nlohmann::json()) != r.value(k, nlohmann::json()))
      return std::string("golden != rtl: ") + k + " " + g.value(k, nlohmann::json()).dump() + " vs " +
             r.value(k, nlohmann::json()).dump();
  return "";
}

}  // namespace

const char* verdict_name(StressVerdict v) {
  switch (v) {
    case StressVerdict::kExact: return "exact";
    case StressVerdict::kFlagged: return "flagged";
    case StressVerdict::kFail: return "FAIL";
  }
  return "?";
}

StressBudget StressBudget::of(const Params& p) {
  auto walk_error = [](const FixFormat& f) { return kLongestWalk * std::ldexp(1.0, -f.frac_bits - 1); };
  return {walk_error(p.ep_d) + std::ldexp(1.0, -p.ep_d.frac_bits - 1),
          1 + static_cast<int>(std::ceil(walk_error(p.ep_color))), 1 + walk_error(p.ep_z)};
}

StressJudgement judge_stress_case(const Trace& triangles, const Params& p, const nlohmann::json& reference_report,
                                  const nlohmann::json& golden_report, const nlohmann::json& rtl_report,
                                  const RgbImage& reference, const RgbImage& golden) {
  (void)reference_report;
  StressJudgement j;
  if (const std::string d = first_difference(golden_report, rtl_report); !d.empty()) {
    j.verdict = StressVerdict::kFail;
    j.why = d;
    return j;
  }
  const StressBudget b = StressBudget::of(p);
  const size_t n = static_cast<size_t>(golden.width) * golden.height;
  Zones z{golden.width, std::vector<uint8_t>(n), std::vector<uint8_t>(n), std::vector<uint8_t>(n), std::vector<float>(n),
          std::vector<uint8_t>(n)};
  if (!triangles.frames.empty()) {
    const TraceFrame& frame = triangles.frames.back();  // frame.png is the last frame
    const std::vector<bool> counted = counted_triangles(frame, p, z);
    for (size_t i = 0; i < frame.triangles.size(); ++i) {
      mark_triangle(frame.triangles[i], frame.settings, p, b, z);
      j.affected_triangles += counted[i];
    }
  }
  int first_x = -1, first_y = -1, worst = 0;
  for (size_t k = 0; k < n; ++k) {
    int diff = 0;
    for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(int(golden.rgb[3 * k + c]) - int(reference.rgb[3 * k + c])));
    if (diff <= b.colour_lsb || z.edge[k] || z.z_conflict[k]) continue;
    ++j.beyond_budget;
    if (z.affected[k]) continue;
    if (j.silent++ == 0) {
      first_x = static_cast<int>(k % golden.width);
      first_y = static_cast<int>(k / golden.width);
    }
    worst = std::max(worst, diff);
  }
  // The warning that names what was counted, on golden and rtl alike (rtl
  // counts no seams: its HAD sees no surfaces).
  auto warned_of = [](const nlohmann::json& report, const char* what) {
    for (const auto& w : report.value("warnings", nlohmann::json::array()))
      if (w.get<std::string>().find(what) != std::string::npos) return true;
    return false;
  };
  const bool limits_warned = (warned_of(golden_report, "EP values in use") || warned_of(golden_report, "the preparer clamped")) &&
                             (warned_of(rtl_report, "EP values in use") || warned_of(rtl_report, "the preparer clamped"));
  const bool seams_warned = warned_of(golden_report, "pixel blends by a surface");
  const uint64_t seams = golden_report.value("pixels_reblended", uint64_t{0});
  if (j.silent > 0) {
    j.verdict = StressVerdict::kFail;
    j.why = std::to_string(j.silent) + " pixel(s) off the reference beyond the budget on triangles nothing counted, "
            "first (" + std::to_string(first_x) + ", " + std::to_string(first_y) + "), up to " + std::to_string(worst) +
            " LSB";
    return j;
  }
  std::string counted;
  bool warned = true;
  if (j.beyond_budget > 0) {
    counted = std::to_string(j.beyond_budget) + " pixel(s) off on " + std::to_string(j.affected_triangles) +
              " counted triangle(s)";
    warned = limits_warned;
  }
  if (seams > 0) {
    counted += std::string(counted.empty() ? "" : "; ") + std::to_string(seams) + " seam pixel(s)";
    warned = warned && seams_warned;
  }
  if (counted.empty()) return j;
  j.verdict = warned ? StressVerdict::kFlagged : StressVerdict::kFail;
  j.why = counted + (warned ? " (warned)" : ", not warned");
  return j;
}

}  // namespace girtd
