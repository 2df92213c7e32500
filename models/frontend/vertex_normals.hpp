// §3 lighting, first half: a polygon's normal (Newell's method, right-handed:
// counter-clockwise seen from the front points toward the viewer) and vertex
// normals averaged over the polygons of the same surface that share the
// vertex. "Share" means the same surface id and bit-identical position, so a
// vertex on two surfaces keeps two normals.
#pragma once

#include <utility>
#include <vector>

#include "frontend/world_frame.hpp"

namespace girtd {

// Newell's sum over the corners at(0..n-1).
template <class At>
Vec3 newell_sum(size_t n, At at) {
  Vec3 sum;
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = at(i);
    const Vec3& b = at((i + 1) % n);
    sum.x += (a.y - b.y) * (a.z + b.z);
    sum.y += (a.z - b.z) * (a.x + b.x);
    sum.z += (a.x - b.x) * (a.y + b.y);
  }
  return sum;
}

// Unnormalized Newell normal: its length is twice the polygon's area for a
// planar polygon; zero for a degenerate one.
Vec3 newell_normal(const std::vector<Vec3>& p);

// Unnormalized Newell normal of the polygon through `positions[index[0..n)]`.
Vec3 newell_normal(const std::vector<Vec3>& positions, const int* index, size_t n);

// normals[i][k] is the unit normal of vertex k of polygon i, held in one
// array for the frame.
class VertexNormals {
 public:
  VertexNormals() = default;
  VertexNormals(std::vector<size_t> first, std::vector<Vec3> normal) : first_(std::move(first)), normal_(std::move(normal)) {}
  const Vec3* operator[](size_t polygon) const { return normal_.data() + first_[polygon]; }
  bool empty() const { return first_.empty(); }

 private:
  std::vector<size_t> first_;  // polygon i's first corner
  std::vector<Vec3> normal_;
};

// The average weighs each polygon's unit normal equally (the thesis'
// "average"), summed in polygon order; a polygon without area
// (polygon_shape.hpp) adds nothing to it.
VertexNormals vertex_normals(const std::vector<WorldPolygon>& polygons);

}  // namespace girtd
