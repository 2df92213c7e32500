// Arithmetic cost of each front-end stage and the preparer, per item, in the
// thesis' flop units (§2, 4.3.3.6): add, subtract, compare, multiply = 1,
// divide = 4, square root = 8. The preparer and the window clip use the
// thesis' own breakdown (172 flop per triangle from its parts: 57 for the
// edge distances in the clip stage, 115 in the preparer; the thesis' total
// of 181 does not add up). The other stages count the operations of the
// algorithms in models/frontend; the derivation of each figure is beside it
// in stage_costs.cpp and tabulated in sim/frontend/README.md. A stage's time
// per item is these flops over its rate (config pipeline.flops_per_s).
#pragma once

#include <cstddef>
#include <cstdint>

#include "config/params.hpp"
#include "frontend/triangulator.hpp"

namespace girtd {

struct OpCount {
  uint64_t add = 0;  // add, subtract, compare, absolute value
  uint64_t mul = 0;
  uint64_t div = 0;
  uint64_t sqrt = 0;
  double flops() const;  // weighted: div 4, sqrt 8
  constexpr OpCount operator+(const OpCount& o) const { return {add + o.add, mul + o.mul, div + o.div, sqrt + o.sqrt}; }
  constexpr OpCount operator*(uint64_t k) const { return {add * k, mul * k, div * k, sqrt * k}; }
};

inline constexpr double kDivFlops = 4, kSqrtFlops = 8;

// The culling stage, in front of lighting: an object's bounding sphere
// against the view volume (culling.objects); a polygon's back-face test (on
// the lighting board where the config builds no culling stage).
OpCount object_culling_ops();
OpCount back_face_ops(size_t corners);
// A polygon of `corners` corners in world space: the no-area test and the
// lighting of every corner by `lights` lights.
OpCount lighting_ops(size_t corners, size_t lights);
// What polygons culling removed would have cost in lighting, the view
// transform and the depth clip's test, from their counts (FrontendCounts).
OpCount culled_ops(uint64_t polygons, uint64_t corners, uint64_t corner_lights);
// Every corner into camera space.
OpCount view_ops(size_t corners);
// The depth test of every corner and `made` crossings at Zs = C.
OpCount depth_clip_ops(size_t corners, size_t made);
// Depth extremes, repeated-corner and area tests, projection and the Zp map.
OpCount projection_ops(size_t corners);
OpCount triangulator_ops(size_t corners, TriangulationMethod method);
// Per triangle: the edge distances (thesis) and the start-point selection.
OpCount window_clip_ops();
// Per frame: the keys of `triangles` triangles and the sort's comparisons.
OpCount depth_sort_ops(size_t triangles, uint64_t comparisons);
// Per triangle (thesis: 3 square roots, 4 divisions, 51 multiplications and
// 81 additions in all, less the clip stage's share), plus the work of the
// preparer's options (config `preparer`): far edges as constants, the
// top-left fill rule. Edge flags cost no arithmetic.
OpCount preparer_ops(const Params& p);
// One attribute plane cut by preparer.steep_attributes limited, on top.
OpCount steep_limit_ops();

}  // namespace girtd
