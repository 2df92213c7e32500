// A polyhedral model as imported: a shared coordinate table and polygons
// indexing it (the thesis' B-rep, fig. 4.39, without the object level), and
// what a model file says of its look: a material per polygon and a diffuse
// colour per polygon corner (vertex colours, a texture's stand-in).
#pragma once

#include <vector>

#include "frontend/vec3.hpp"

namespace girtd {

// A diffuse reflectance as a colour, 0..255 a channel: it stands in for the
// surface's R, G, B at that corner (vertex_lighting.hpp).
struct CornerColour {
  float r = 0, g = 0, b = 0;
};

struct Mesh {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> polygons;  // indices into positions, counter-clockwise from outside
  // Empty, or one per polygon: its material's index in the importer's list.
  std::vector<int> material;
  // Empty, or one per corner, polygon after polygon (corner k of polygon i
  // after the corners of polygons 0..i-1): the corner's own diffuse colour.
  std::vector<CornerColour> corner_colour;
};

}  // namespace girtd
