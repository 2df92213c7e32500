// Splits a model into surfaces for the vertex-normal average (§3): polygons
// that share an edge join one surface when their normals differ by at most
// `crease_deg`. A cube (90 deg edges) becomes 6 flat surfaces with the
// default crease, a finely tessellated sphere one smooth surface; 180 makes
// every connected piece smooth, 0 every polygon flat. Polygons of different
// materials (Mesh::material) never share a surface, while they are drawn.
#pragma once

#include <vector>

#include "frontend/mesh.hpp"

namespace girtd {

// Default crease angle for models without one (models/frontend/README.md).
inline constexpr double kDefaultCreaseDeg = 60.0;

// group[i] is the surface of polygon i, numbered 0..count-1 in order of first use.
struct SurfaceGroups {
  std::vector<int> group;
  int count = 0;
};

// `split_materials` false: the materials are not drawn (a scene names its
// own), so their borders split nothing.
SurfaceGroups surface_groups(const Mesh& mesh, double crease_deg, bool split_materials = true);

}  // namespace girtd
