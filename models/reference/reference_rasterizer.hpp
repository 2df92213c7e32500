// The floating-point yardstick: the same triangles in double precision,
// coverage by Norm_Q of the exact edge distances at every lattice point of the
// Q-widened box, Gouraud attributes from the exact planes. It draws the pixel
// set the DDA is meant to draw, with no fixed-point error.
#pragma once

#include <array>
#include <functional>

#include "common/triangle_setup.hpp"
#include "common/types.hpp"

namespace girtd {

struct ReferenceSample {
  int x = 0, y = 0;
  double r = 0, g = 0, b = 0, t = 0, z = 0;  // unclamped plane values
  std::array<double, 3> d{};                  // edge distances
  double nf = 0;                              // T n1 n2 n3, T clamped to 0..1
  int layer = -1;                             // seam_layer() of the triangle
  bool covered = false;                       // inside the triangle: not in a fringe, not on a soft edge
};

using ReferenceSink = std::function<void(const ReferenceSample&)>;

// The preparer's edge options (config `preparer`) that change which pixels
// the ideal picture holds: a shared edge's pixels drawn once, interior
// edges without a fringe.
struct EdgeRules {
  bool top_left = false;
  bool edge_flags = false;
};

// A triangle's three edges as the rules measure them: the distance (from
// the shared evaluation with the top-left rule), each edge's fringe (none
// on an interior edge with edge flags) and the inside test with its ties.
// The reference draws by it; girtd stress's budget measures by it.
class RuleEdges {
 public:
  RuleEdges(const TriangleSetup& s, const FrameSettings& f, const EdgeRules& rules);
  double distance(int i, double x, double y) const {
    return top_left_ ? shared_[i].at(x, y) : s_.edge[i].at(x, y);
  }
  double q(int i) const { return q_[i]; }
  bool inside(int i, double d) const {
    if (q_[i] > 0) return d > -q_[i];
    return d > 0 || (d == 0 && (!top_left_ || shared_[i].owns_ties()));
  }

 private:
  const TriangleSetup& s_;
  bool top_left_;
  std::array<SharedEdge, 3> shared_;
  std::array<double, 3> q_;
};

// Emits every lattice pixel inside the fringe box with all D_i > -Q (Q > 0)
// or all D_i >= 0 (Q = 0). Returns false when the triangle is discarded
// (no area, or it misses the window).
bool rasterize_reference(const Triangle& t, const FrameSettings& f, const EdgeRules& rules,
                         const ReferenceSink& sink);

// The HAD's view of a sample, with the hardware's output rules: truncation,
// saturation to 0..255 / 0..65535, nf as 1.8.
Pixel quantize_reference(const ReferenceSample& s);

}  // namespace girtd
