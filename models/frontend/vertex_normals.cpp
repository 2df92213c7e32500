#include "frontend/vertex_normals.hpp"

#include <tuple>

#include "common/equal_keys.hpp"
#include "frontend/polygon_shape.hpp"

namespace girtd {

Vec3 newell_normal(const std::vector<Vec3>& p) {
  return newell_sum(p.size(), [&](size_t i) -> const Vec3& { return p[i]; });
}

Vec3 newell_normal(const std::vector<Vec3>& positions, const int* index, size_t n) {
  return newell_sum(n, [&](size_t i) -> const Vec3& { return positions[size_t(index[i])]; });
}

Vec3 face_normal(const std::vector<Vec3>& p) { return has_no_area(p) ? Vec3{} : normalized(newell_normal(p)); }

VertexNormals vertex_normals(const std::vector<WorldPolygon>& polygons) {
  std::vector<uint64_t> first(polygons.size());
  std::vector<Vec3> face(polygons.size());
  std::vector<uint32_t> polygon_of;  // per corner
  for (size_t i = 0; i < polygons.size(); ++i) {
    const WorldPolygon& poly = polygons[i];
    first[i] = polygon_of.size();
    face[i] = face_normal(poly.p);  // no area: no direction
    polygon_of.insert(polygon_of.end(), poly.p.size(), uint32_t(i));
  }
  std::vector<uint32_t> vertex_of(polygon_of.size());
  std::vector<Vec3> vertex_normal;
  const auto key_of = [&](size_t c) {
    const WorldPolygon& poly = polygons[polygon_of[c]];
    const Vec3& v = poly.p[c - first[polygon_of[c]]];
    return std::make_tuple(poly.surface, same_zero(v.x), same_zero(v.y), same_zero(v.z));
  };
  // The corners of one vertex come in polygon order: the sum adds in that order.
  for_each_equal_key(polygon_of.size(), key_of, [&](const uint32_t* corner, size_t n) {
    Vec3 sum;
    for (size_t k = 0; k < n; ++k) sum = sum + face[polygon_of[corner[k]]];
    for (size_t k = 0; k < n; ++k) vertex_of[corner[k]] = uint32_t(vertex_normal.size());
    vertex_normal.push_back(normalized(sum));
  });
  return VertexNormals(&polygons, std::move(first), std::move(vertex_of), std::move(vertex_normal));
}

}  // namespace girtd
