// §3 depth clip at Zs = C, on polygons in camera space (Sutherland-Hodgman
// against one plane): vertices with Zs > C stay; each edge crossing the plane
// gets a new vertex at the crossing, with position and attributes
//   P = (P1 (C - Zs2) + P2 (Zs1 - C)) / (Zs1 - Zs2),  Zs1 > C >= Zs2
// (the corrected weights: the thesis prints them swapped). For a triangle
// this is the thesis' four cases: 0 vertices in front -> nothing, 3 -> as
// is, 1 -> a smaller triangle, 2 -> a quadrilateral.
#pragma once

#include <vector>

#include "frontend/camera_vertex.hpp"

namespace girtd {

// The edge P1 -> P2 cut at Zs = C; requires p1.s.z > c >= p2.s.z.
CameraVertex depth_crossing(const CameraVertex& p1, const CameraVertex& p2, double c);

// The part of the polygon with Zs > C, in the same order (empty if none).
std::vector<CameraVertex> depth_clip(const std::vector<CameraVertex>& poly, double c);
// The same into `out` (cleared first, its storage reused; not `poly` itself).
void depth_clip(const std::vector<CameraVertex>& poly, double c, std::vector<CameraVertex>& out);

}  // namespace girtd
