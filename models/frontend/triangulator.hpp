// §3 triangulator: an n-gon into n - 2 triangles, no new vertices.
//   no concave vertex  -> fan from vertex 0
//   one concave vertex -> fan from it (a polygon with one reflex vertex is
//                         star-shaped from that vertex)
//   more               -> ear clipping (the thesis' "special processing")
// A vertex is concave when the z of the cross product of its two edges has
// the sign opposite to the polygon's area, and straight (neither convex nor
// concave: not counted, never an ear) when that z is within
// kStraightTolerance of |e1||e2| (the sine of the turn), which rounding
// cannot leave. Works on 2D points: the front end
// passes the polygon projected onto its own (Newell) plane, so a non-planar
// polygon is split the same way from every viewpoint.
#pragma once

#include <array>
#include <vector>

namespace girtd {

inline constexpr double kStraightTolerance = 1e-9;

struct Point2 {
  double x = 0, y = 0;
};

struct TriangleIndices {
  std::array<int, 3> v{};
  // made_edge[i]: the edge v[i] -> v[(i+1)%3] is a diagonal the triangulator
  // made, not a polygon edge (the wire-frame mode draws only polygon edges).
  std::array<bool, 3> made_edge{};
};

enum class TriangulationMethod { kConvexFan, kConcaveFan, kEarClipping, kFallbackFan };

struct Triangulation {
  std::vector<TriangleIndices> triangles;
  TriangulationMethod method = TriangulationMethod::kConvexFan;
  int concave_vertices = 0;
};

// `p` needs at least 3 points. A self-intersecting polygon, where ear
// clipping finds no ear, is fanned from vertex 0 (method kFallbackFan).
Triangulation triangulate(const std::vector<Point2>& p);
// The same into `out`, whose storage is reused (a front end's per-polygon loop).
void triangulate(const std::vector<Point2>& p, Triangulation& out);

}  // namespace girtd
