// A polyhedral model as imported: a shared coordinate table and polygons
// indexing it (the thesis' B-rep, fig. 4.39, without the object level), and
// what a model file says of its look: a material per polygon and a diffuse
// colour per polygon corner (vertex colours, a texture's stand-in). Flat
// arrays: a million-triangle model is a handful of allocations, not one per
// polygon.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "frontend/vec3.hpp"

namespace girtd {

// A diffuse reflectance as a colour, 0..255 a channel: it stands in for the
// surface's R, G, B at that corner (vertex_lighting.hpp).
struct CornerColour {
  float r = 0, g = 0, b = 0;
};

// A polygon's corners: `size` position indices from `data`.
struct CornerSpan {
  const int* data = nullptr;
  size_t size = 0;
  const int* begin() const { return data; }
  const int* end() const { return data + size; }
  int operator[](size_t k) const { return data[k]; }
};

struct Mesh {
  std::vector<Vec3> positions;
  // Every polygon's position indices, counter-clockwise from outside,
  // polygon after polygon: polygon i is corners[first[i] .. first[i + 1]).
  std::vector<int> corners;
  std::vector<uint64_t> first{0};
  // Empty, or one per polygon: its material's index in the importer's list.
  std::vector<int> material;
  // Empty, or one per corner (parallel to `corners`): the corner's own
  // diffuse colour.
  std::vector<CornerColour> corner_colour;

  size_t polygon_count() const { return first.size() - 1; }
  CornerSpan polygon(size_t i) const { return {corners.data() + first[i], size_t(first[i + 1] - first[i])}; }
  template <class It>
  void add_polygon(It begin, It end) {
    corners.insert(corners.end(), begin, end);
    first.push_back(corners.size());
  }
};

}  // namespace girtd
