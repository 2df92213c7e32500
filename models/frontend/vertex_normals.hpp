// §3 lighting, first half: a polygon's normal (Newell's method, right-handed:
// counter-clockwise seen from the front points toward the viewer) and vertex
// normals averaged over the polygons of the same surface that share the
// vertex. "Share" means the same surface id and bit-identical position, so a
// vertex on two surfaces keeps two normals.
#pragma once

#include <vector>

#include "frontend/world_frame.hpp"

namespace girtd {

// Unnormalized Newell normal: its length is twice the polygon's area for a
// planar polygon; zero for a degenerate one.
Vec3 newell_normal(const std::vector<Vec3>& p);

// normals[i][k] is the unit normal of vertex k of polygon i. The average
// weighs each polygon's unit normal equally (the thesis' "average"); a
// polygon without area (polygon_shape.hpp) adds nothing to it.
std::vector<std::vector<Vec3>> vertex_normals(const std::vector<WorldPolygon>& polygons);

}  // namespace girtd
