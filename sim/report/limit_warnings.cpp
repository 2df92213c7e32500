#include "report/limit_warnings.hpp"

#include <set>

namespace girtd {

namespace {

// The config key of an EP's format and its integer bits now.
std::string widen_key(int ep, const Params& p) {
  if (ep >= kEpD1) return "ep.d.int_bits above " + std::to_string(p.ep_d.int_bits);
  if (ep == kEpZ) return "ep.z.int_bits above " + std::to_string(p.ep_z.int_bits);
  if (ep == kEpT) return "ep.t.int_bits above " + std::to_string(p.ep_t.int_bits);
  return "ep.color.int_bits above " + std::to_string(p.ep_color.int_bits);
}

}  // namespace

std::optional<std::string> wrap_warning(const std::string& input, const RunStats& s, const Params& p) {
  if (!s.dda || s.dda->numerics.wraps() == 0) return std::nullopt;
  const EpNumerics& n = s.dda->numerics;
  std::string eps, keys;
  std::set<std::string> seen;
  for (int i = 0; i < kEpCount; ++i) {
    if (!n.ep[i].wraps) continue;
    eps += std::string(eps.empty() ? "" : ", ") + kEpNames[i] + " " + std::to_string(n.ep[i].wraps) + " times";
    if (seen.insert(widen_key(i, p)).second) keys += (keys.empty() ? "" : " and ") + widen_key(i, p);
  }
  std::string first = "triangle " + std::to_string(n.first_affected);
  if (n.first_affected_line > 0) first += " (line " + std::to_string(n.first_affected_line) + ")";
  return input + ": wrapped EP values in use (" + eps + ") in " + std::to_string(n.triangles_affected) +
         " triangle(s), the first " + first + ": the picture is wrong there. A --config file setting " + keys +
         " avoids it (on rtl, an RTL variant is built for it)";
}

}  // namespace girtd
