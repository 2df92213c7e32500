#include "dda/dda_preparer.hpp"

#include <algorithm>
#include <cmath>

#include "common/fixed_point.hpp"
#include "common/triangle_setup.hpp"

namespace girtd {

PrepareResult DdaPreparer::prepare(const Triangle& t, const FrameSettings& f, DdaParams& out) {
  const auto setup = setup_triangle(t);
  if (!setup) {
    ++counts_.degenerate;
    return PrepareResult::kDegenerate;
  }
  const TriangleSetup& s = *setup;
  const auto start = select_start_point(s, f.window);
  const PixelBox box = fringe_box(s, f.q, f.window);
  if (!start || box.empty()) {
    ++counts_.off_window;
    return PrepareResult::kOffWindow;
  }
  // Start row: the first lattice row at or below the start point's Q-fringe;
  // start column: the start point rounded, kept inside the limits.
  const int y0 = std::max(static_cast<int>(std::ceil(start->y - f.q)), box.y0);
  const int x0 = std::clamp(static_cast<int>(std::floor(start->x + 0.5)), box.x0, box.x1);
  if (y0 > box.y1) {
    ++counts_.no_lattice_row;
    return PrepareResult::kNoLatticeRow;
  }
  out = DdaParams{};
  out.x0 = x0;
  out.y0 = y0;
  out.xmin = box.x0;
  out.xmax = box.x1;
  out.ymax = box.y1;
  out.q = f.q;
  out.source_line = t.source_line;

  auto convert = [&](double v, double dx, double dy, const FixFormat& fmt, EpInit& ep) {
    bool c1 = false, c2 = false, c3 = false;
    ep.v = to_fixed(v, fmt, &c1);
    ep.dx = to_fixed(dx, fmt, &c2);
    ep.dy = to_fixed(dy, fmt, &c3);
    counts_.clamps[size_t(&ep - &out.ep[0])] += c1 + c2 + c3;
    out.clamped = out.clamped || c1 || c2 || c3;
  };
  // T is carried on a 0..256 scale so that its 8-bit output saturates to 255 = 1.0.
  const double attr_scale[kAttrCount] = {1, 1, 1, 256, 1};
  const Ep attr_ep[kAttrCount] = {kEpR, kEpG, kEpB, kEpT, kEpZ};
  const FixFormat* attr_fmt[kAttrCount] = {&params_.ep_color, &params_.ep_color, &params_.ep_color,
                                           &params_.ep_t, &params_.ep_z};
  for (int a = 0; a < kAttrCount; ++a) {
    const AttributePlane& pl = s.attr[a];
    const double k = attr_scale[a];
    convert(k * pl.at(x0, y0), k * pl.dx, k * pl.dy, *attr_fmt[a], out.ep[attr_ep[a]]);
  }
  for (int i = 0; i < 3; ++i) {
    const EdgeEquation& e = s.edge[i];
    convert(e.at(x0, y0), e.a, e.b, params_.ep_d, out.ep[kEpD1 + i]);
  }
  ++counts_.prepared;
  return PrepareResult::kReady;
}

}  // namespace girtd
