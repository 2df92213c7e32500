#include "report/limit_warnings.hpp"

#include <set>

namespace girtd {

namespace {

// The config key of an EP's format and its integer bits now.
std::string widen_key(int ep, const Params& p) {
  if (ep >= kEpD1)
    return "preparer.far_edges \"constant\" (config/presets/robust.json) or ep.d.int_bits above " +
           std::to_string(p.ep_d.int_bits);
  if (ep == kEpZ) return "ep.z.int_bits above " + std::to_string(p.ep_z.int_bits);
  if (ep == kEpT) return "ep.t.int_bits above " + std::to_string(p.ep_t.int_bits);
  return "ep.color.int_bits above " + std::to_string(p.ep_color.int_bits);
}

// "D1 548 clocks, R 3 pixels" for the EPs with a nonzero count.
template <typename Count>
std::string per_ep(Count count, std::set<std::string>& keys, const Params& p) {
  std::string out;
  for (int i = 0; i < kEpCount; ++i) {
    const uint64_t n = count(i);
    if (!n) continue;
    out += std::string(out.empty() ? "" : ", ") + kEpNames[i] + " " + std::to_string(n);
    keys.insert(widen_key(i, p));
  }
  return out;
}

}  // namespace

std::optional<std::string> limit_warning(const std::string& input, const RunStats& s, const Params& p) {
  if (!s.dda || s.dda->numerics.triangles_affected == 0) return std::nullopt;
  const EpNumerics& n = s.dda->numerics;
  std::set<std::string> keys;
  const std::string wraps = per_ep([&](int i) { return n.ep[i].wraps; }, keys, p);
  const std::string clamps =
      s.preparer ? per_ep([&](int i) { return s.preparer->clamps[i]; }, keys, p) : std::string();
  std::string what;
  if (!wraps.empty()) what = "wrapped EP values in use (" + wraps + "; D: clocks that tested it, others: pixels)";
  if (!clamps.empty()) what += (what.empty() ? "" : " and ") + std::string("values the preparer clamped (") + clamps + ")";
  std::string first = "triangle " + std::to_string(n.first_affected) + " drawn";
  if (n.first_affected_line > 0) first += " (line " + std::to_string(n.first_affected_line) + ")";
  std::string settings;
  for (const std::string& k : keys) settings += (settings.empty() ? "" : " and ") + k;
  bool attributes = false;  // R, G, B, T or Z: steep planes, which the preparer can cut instead
  for (int i = 0; i < kEpD1; ++i) attributes = attributes || n.ep[i].wraps || (s.preparer && s.preparer->clamps[i]);
  const std::string steep = attributes && !p.steep_limited
                                ? "; for R, G, B, T and Z, so does preparer.steep_attributes \"limited\" "
                                  "(config/presets/robust.json), with no variant"
                                : "";
  return input + ": " + what + " in " + std::to_string(n.triangles_affected) + " triangle(s); first: " + first +
         ": the picture is wrong there. A --config file setting " + settings +
         " avoids it (on rtl, an RTL variant is built for it)" + steep;
}

std::optional<std::string> seam_warning(const std::string& input, const RunStats& s) {
  if (s.had.reblended == 0) return std::nullopt;
  return input + ": " + std::to_string(s.had.reblended) +
         " pixel blends by a surface that had already blended the pixel (seams at shared edges: drawn twice, "
         "or a neighbour's antialiasing fringe). A --config file setting preparer.fill_rule \"top_left\" and "
         "preparer.edge_flags true (config/presets/robust.json) avoids it";
}

std::optional<std::string> culling_warning(const std::string& input, const RunStats& s) {
  if (!s.frontend || s.frontend->back_faces_exempt == 0) return std::nullopt;
  std::string ids;
  for (int id : s.frontend->exempt_surfaces) ids += (ids.empty() ? "" : ", ") + std::to_string(id);
  return input + ": " + std::to_string(s.frontend->back_faces_exempt) +
         " back faces of transparent surfaces (" + ids +
         ") were not culled: culling.back_faces \"always\" exempts them, since they show through the front faces "
         "(set the input's own cull_back_faces / cull to cull them anyway)";
}

}  // namespace girtd
