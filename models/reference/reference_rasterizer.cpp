#include "reference/reference_rasterizer.hpp"

#include <algorithm>
#include <cmath>

namespace girtd {
namespace {

int floor_clamped(double v, int hi) {
  if (!(v >= 0)) return 0;
  if (v >= hi) return hi;
  return static_cast<int>(std::floor(v));
}

}  // namespace

RuleEdges::RuleEdges(const TriangleSetup& s, const FrameSettings& f, const EdgeRules& rules)
    : s_(s), top_left_(rules.top_left) {
  for (int i = 0; i < 3; ++i) {
    if (top_left_) shared_[i] = shared_edge(s, i, f.window);
    q_[i] = rules.edge_flags && s.interior[i] ? 0.0 : f.q;
  }
}

bool rasterize_reference(const Triangle& t, const FrameSettings& f, const EdgeRules& rules,
                         const ReferenceSink& sink) {
  const auto setup = setup_triangle(t);
  if (!setup || !select_start_point(*setup, f.window)) return false;
  const TriangleSetup& s = *setup;
  const PixelBox box = fringe_box(s, f.q, f.window);
  const RuleEdges edges(s, f, rules);
  ReferenceSample smp;
  smp.layer = seam_layer(t, s);
  for (int y = box.y0; y <= box.y1; ++y) {
    for (int x = box.x0; x <= box.x1; ++x) {
      bool inside = true;
      double n = 1.0;
      for (int i = 0; i < 3; ++i) {
        smp.d[i] = edges.distance(i, x, y);
        inside = inside && edges.inside(i, smp.d[i]);
        n *= norm_q(smp.d[i], edges.q(i));
      }
      if (!inside) continue;
      smp.x = x;
      smp.y = y;
      smp.r = s.attr[kR].at(x, y);
      smp.g = s.attr[kG].at(x, y);
      smp.b = s.attr[kB].at(x, y);
      smp.t = s.attr[kT].at(x, y);
      smp.z = s.attr[kZ].at(x, y);
      smp.nf = std::clamp(smp.t, 0.0, 1.0) * n;
      smp.covered = n == 1.0;  // and not on a soft edge (the boundary, as models/dda counts it)
      for (int i = 0; i < 3; ++i)
        if (edges.q(i) > 0 && smp.d[i] == 0) smp.covered = false;
      sink(smp);
    }
  }
  return true;
}

Pixel quantize_reference(const ReferenceSample& s) {
  Pixel p;
  p.x = s.x;
  p.y = s.y;
  p.r = static_cast<uint8_t>(floor_clamped(s.r, 255));
  p.g = static_cast<uint8_t>(floor_clamped(s.g, 255));
  p.b = static_cast<uint8_t>(floor_clamped(s.b, 255));
  p.z = static_cast<uint16_t>(floor_clamped(s.z, 65535));
  p.nf = static_cast<uint16_t>(floor_clamped(s.nf * kNfOne, kNfOne));
  return p;
}

}  // namespace girtd
