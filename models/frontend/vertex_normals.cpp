#include "frontend/vertex_normals.hpp"

#include <map>
#include <tuple>

#include "frontend/polygon_shape.hpp"

namespace girtd {

Vec3 newell_normal(const std::vector<Vec3>& p) {
  Vec3 n;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % p.size()];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

std::vector<std::vector<Vec3>> vertex_normals(const std::vector<WorldPolygon>& polygons) {
  using Key = std::tuple<int, double, double, double>;
  std::map<Key, Vec3> sum;
  std::vector<Vec3> face(polygons.size());
  for (size_t i = 0; i < polygons.size(); ++i) {
    const WorldPolygon& poly = polygons[i];
    face[i] = has_no_area(poly.p) ? Vec3{} : normalized(newell_normal(poly.p));  // no area: no direction
    for (const Vec3& v : poly.p) {
      Vec3& s = sum[Key{poly.surface, v.x, v.y, v.z}];
      s = s + face[i];
    }
  }
  std::vector<std::vector<Vec3>> out(polygons.size());
  for (size_t i = 0; i < polygons.size(); ++i) {
    const WorldPolygon& poly = polygons[i];
    out[i].reserve(poly.p.size());
    for (const Vec3& v : poly.p) {
      const Vec3 avg = normalized(sum[Key{poly.surface, v.x, v.y, v.z}]);
      // Opposite faces of a sheet cancel: fall back to the polygon's own normal.
      out[i].push_back(length(avg) > 0 ? avg : face[i]);
    }
  }
  return out;
}

}  // namespace girtd
