// §3 lighting, first half: a polygon's normal (Newell's method, right-handed:
// counter-clockwise seen from the front points toward the viewer) and vertex
// normals averaged over the polygons of the same surface that share the
// vertex. "Share" means the same surface id and bit-identical position, so a
// vertex on two surfaces keeps two normals.
#pragma once

#include <cstdint>
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

// The polygon's own unit normal, zero for one without area.
Vec3 face_normal(const std::vector<Vec3>& p);

// at(i, k) is the unit normal of vertex k of polygon i. Held as one normal
// per shared vertex and a vertex per corner (a 10^6-triangle frame: 32 MB,
// not a normal per corner's 80).
class VertexNormals {
 public:
  VertexNormals() = default;
  VertexNormals(const std::vector<WorldPolygon>* polygons, std::vector<uint64_t> first, std::vector<uint32_t> vertex_of,
                std::vector<Vec3> vertex_normal)
      : polygons_(polygons), first_(std::move(first)), vertex_of_(std::move(vertex_of)), normal_(std::move(vertex_normal)) {}
  Vec3 at(size_t polygon, size_t k) const {
    const Vec3& n = normal_[vertex_of_[first_[polygon] + k]];
    // Opposite faces of a sheet cancel: the polygon's own normal then.
    return length(n) > 0 ? n : face_normal((*polygons_)[polygon].p);
  }
  bool empty() const { return first_.empty(); }

 private:
  const std::vector<WorldPolygon>* polygons_ = nullptr;
  std::vector<uint64_t> first_;     // polygon i's first corner
  std::vector<uint32_t> vertex_of_;  // each corner's shared vertex
  std::vector<Vec3> normal_;         // each shared vertex's normal (zero where its faces cancel)
};

// The average weighs each polygon's unit normal equally (the thesis'
// "average"), summed in polygon order; a polygon without area
// (polygon_shape.hpp) adds nothing to it.
// The result refers to `polygons`, which must outlive it.
VertexNormals vertex_normals(const std::vector<WorldPolygon>& polygons);
VertexNormals vertex_normals(const std::vector<WorldPolygon>&& polygons) = delete;

}  // namespace girtd
