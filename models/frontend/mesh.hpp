// A polyhedral model as imported: a shared coordinate table and polygons
// indexing it (the thesis' B-rep, fig. 4.39, without the object level).
#pragma once

#include <vector>

#include "frontend/vec3.hpp"

namespace girtd {

struct Mesh {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> polygons;  // indices into positions, counter-clockwise from outside
};

}  // namespace girtd
