#include "frontend/stage_costs.hpp"

namespace girtd {

double OpCount::flops() const {
  return double(add) + double(mul) + kDivFlops * double(div) + kSqrtFlops * double(sqrt);
}

namespace {

// Newell normal: per corner 3 x (2 add + 1 mul).
constexpr OpCount kNewellCorner{6, 3, 0, 0};
OpCount newell(size_t n) { return kNewellCorner * n; }
// |v| of a 3-vector: 3 mul, 2 add, 1 sqrt; normalizing adds 1 div and 3 mul.
constexpr OpCount kLength{2, 3, 0, 1};
constexpr OpCount kNormalize{2, 6, 1, 1};
constexpr OpCount kDot{2, 3, 0, 0};

// polygon_shape's no-area test: Newell normal, its length, the perimeter
// (a length per edge) and one compare: a fixed part and a part per corner.
constexpr OpCount kAreaTestFixed = kLength + OpCount{1, 2, 0, 0};
constexpr OpCount kAreaTestPerCorner = kNewellCorner + kLength + OpCount{4, 0, 0, 0};

// Lighting per corner: E = unit(eye - P) (3 sub + normalize); ambient R Id
// (3 mul); transparency Tf = Tmin + (Tmax - Tmin)|N.E|, T = 1 - Tf (dot,
// abs, 3 add, 1 mul); saturation of R, G, B and T (8 compares).
constexpr OpCount kLightCorner = OpCount{3, 0, 0, 0} + kNormalize + OpCount{0, 3, 0, 0} + kDot +
                                 OpCount{4, 1, 0, 0} + OpCount{8, 0, 0, 0};
// Per corner and light: N.I and its sign; diffuse R If (N.I) per colour
// (2 mul, 1 add); reflection 2(N.I)N - I (4 mul, 3 sub) and its dot with E,
// clamp; the power by exp(n ln x) (two series, as a square root each, plus
// 1 mul); the angle acos(N.I) (as a square root); CRE interpolation (1 div,
// 2 add, 1 mul); 255 CRE pow If (3 mul) added to each colour (3 add).
constexpr OpCount kLightCornerLight = kDot + OpCount{1, 0, 0, 0} + OpCount{3, 6, 0, 0} + OpCount{3, 4, 0, 0} + kDot +
                                      OpCount{1, 0, 0, 0} + OpCount{0, 1, 0, 2} + OpCount{0, 0, 0, 1} +
                                      OpCount{2, 1, 1, 0} + OpCount{3, 3, 0, 0};

// The view transform per corner: [Xs Ys Zs] = (P - C) T, 3 sub, 9 mul, 6 add.
constexpr OpCount kViewCorner{9, 9, 0, 0};
// The depth clip's test per corner: one compare.
constexpr OpCount kDepthTestCorner{1, 0, 0, 0};

}  // namespace

// Linear in corners and corners x lights, so culled_ops can sum it.
OpCount lighting_ops(size_t n, size_t lights) {
  return kAreaTestFixed + (kAreaTestPerCorner + kLightCorner) * n + kLightCornerLight * (n * lights);
}

// The centre of the stored sphere into camera space (as a corner in view);
// the radius scaled by the object's scale (1 mul); the near test (1 add, 1
// compare); the four sides through the eye, their unit normals set once a
// frame (2 mul, 1 add, 1 compare each).
OpCount object_culling_ops() { return kViewCorner + OpCount{0, 1, 0, 0} + OpCount{2, 0, 0, 0} + OpCount{2, 2, 0, 0} * 4; }

// The polygon's normal is stored with its vertex normals (a zero normal
// marks no area: 1 compare); centroid (3 add per corner, 1/n: 1 div, 3 mul),
// the vector to the eye (3 sub), one dot, one compare.
OpCount back_face_ops(size_t n) { return OpCount{3 * n + 5, 3, 1, 0} + kDot; }

OpCount culled_ops(uint64_t polygons, uint64_t corners, uint64_t corner_lights) {
  return kAreaTestFixed * polygons + (kAreaTestPerCorner + kLightCorner + kViewCorner + kDepthTestCorner) * corners +
         kLightCornerLight * corner_lights;
}

OpCount view_ops(size_t n) { return kViewCorner * n; }

// One compare per corner; per crossing the weights (3 sub, 1 div) and
// 7 attributes (X, Y, Z, R, G, B, T) at 2 mul + 1 add each.
OpCount depth_clip_ops(size_t n, size_t made) {
  return kDepthTestCorner * n + (OpCount{3, 0, 1, 0} + OpCount{7, 14, 0, 0}) * made;
}

// Per corner: the screen box (4 compares) and Zmin/Zmax (2 compares),
// repeated-corner test (3 compares), 1/Zs (1 div), Xp and Yp (4 mul), the
// pixel map (2 add, 2 mul), Zp (1 add, 2 mul): 12 add, 8 mul, 1 div; per
// polygon the box against the window (4 compares); plus the area test the
// clip's slivers need.
OpCount projection_ops(size_t n) {
  return OpCount{12, 8, 1, 0} * n + OpCount{4, 0, 0, 0} + kAreaTestFixed + kAreaTestPerCorner * n;
}

// The polygon's own plane (Newell normal, normalize, two axes: 2 cross
// products, 1 normalize; per corner 2 dots and 3 sub, 1 compare for the
// planarity); the turn of every corner (2 mul, 3 sub, 1 compare). Ear
// clipping tests every remaining corner against each candidate ear
// (2 x 3 mul + 5 add per test), about n^2 tests per polygon.
OpCount triangulator_ops(size_t n, TriangulationMethod method) {
  OpCount ops = newell(n) + kNormalize * 2 + OpCount{6, 12, 0, 0} + (kDot * 2 + OpCount{4, 0, 0, 0}) * n +
                OpCount{4, 2, 0, 0} * n;
  if (method == TriangulationMethod::kEarClipping || method == TriangulationMethod::kFallbackFan)
    ops = ops + OpCount{5, 6, 0, 0} * (n * n);
  return ops;
}

// The thesis' figure for the edge distances, 57 flop per triangle, kept as
// stated (as additions: the thesis gives the total, not its mix).
OpCount window_clip_ops() { return OpCount{57, 0, 0, 0}; }

// The key (the farthest corner: 2 compares) and one compare per comparison.
OpCount depth_sort_ops(size_t triangles, uint64_t comparisons) { return OpCount{2 * triangles + comparisons, 0, 0, 0}; }

// 3 sqrt, 4 div, 51 mul and 81 add make 172 flop; less the clip stage's 57,
// the preparer's 115 (as additions, like the clip's share).
// Far edges: per edge, D at the two box corners where it is least and most
// (2 mul, 2 add each) and two compares: 3 x (4 mul + 6 add).
// Top-left rule: per edge, the window's middle projected onto the edge
// (4 sub, 2 dot products of 2 mul + 1 add, 1 div, 2 compares to clamp, the
// point: 2 mul + 2 add, 2 roundings as adds), D at that lattice point
// (2 sub, 2 mul, 1 add), D at the start pixel from it (2 sub, 2 mul, 2 add)
// and the tie test and bias (2 compares, 1 add): 3 x (22 add, 10 mul, 1 div).
// Steep attributes (models/dda/steep_attributes.cpp), upper bounds: the
// region where the DDA may emit, once a triangle: the centroid (4 add, 2
// mul), the longest edge (3 x (3 add, 2 mul, 1 sqrt), 3 compares, 2 div),
// the grown corners (3 x (6 mul, 5 add, 2 div)), the clip to the box (4
// sides x (7 points x 2 add, 2 crossings x (5 add, 2 mul, 1 div))), the
// corners from the centroid (16 add); then per plane (5) its value at the
// centroid (2 mul, 3 add) and the fit test (2 derivative compares, 8 corners
// x (2 mul, 2 add, 2 compares)): 143 + 5 x 39 add, 42 + 5 x 18 mul, 16 div,
// 3 sqrt.
OpCount preparer_ops(const Params& p) {
  OpCount ops{115, 0, 0, 0};
  if (p.far_edges_constant) ops = ops + OpCount{6, 4, 0, 0} * 3;
  if (p.fill_top_left) ops = ops + OpCount{22, 10, 1, 0} * 3;
  if (p.steep_limited) ops = ops + OpCount{143, 42, 16, 3} + OpCount{39, 18, 0, 0} * 5;
  return ops;
}

// A plane cut (models/dda/steep_attributes.cpp), upper bounds: the parts
// along and across the longest edge (4 mul, 2 add); the along part at 8
// corners (4 mul, 5 add, 1 div each); the across interval at 8 corners (3
// mul, 9 add, 2 div each) and its clamp (4 compares); the new derivatives
// (4 mul, 2 add), their bound (3 compares, 1 div, 2 mul) and the start value
// (2 mul, 4 add).
OpCount steep_limit_ops() { return OpCount{127, 68, 25, 0}; }

}  // namespace girtd
