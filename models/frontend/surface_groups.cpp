#include "frontend/surface_groups.hpp"

#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include "frontend/vertex_normals.hpp"

namespace girtd {

SurfaceGroups surface_groups(const Mesh& mesh, double crease_deg, bool split_materials) {
  const size_t n = mesh.polygons.size();
  std::vector<size_t> parent(n);
  std::iota(parent.begin(), parent.end(), size_t{0});
  auto find = [&](size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  std::vector<Vec3> normal(n);
  for (size_t i = 0; i < n; ++i) {
    std::vector<Vec3> p;
    for (int k : mesh.polygons[i]) p.push_back(mesh.positions[static_cast<size_t>(k)]);
    normal[i] = normalized(newell_normal(p));
  }
  // Allow rounding: a crease of exactly 90 deg joins 90-deg neighbours.
  const double min_cos = std::cos(crease_deg * M_PI / 180.0) - 1e-9;
  std::map<std::pair<int, int>, size_t> edge_owner;  // undirected edge -> first polygon seen on it
  for (size_t i = 0; i < n; ++i) {
    const std::vector<int>& poly = mesh.polygons[i];
    for (size_t k = 0; k < poly.size(); ++k) {
      int a = poly[k], b = poly[(k + 1) % poly.size()];
      if (a > b) std::swap(a, b);
      auto [it, fresh] = edge_owner.emplace(std::make_pair(a, b), i);
      if (fresh) continue;
      const size_t j = it->second;
      // Two materials are two surfaces, however smooth the edge between them.
      const bool same_material = !split_materials || mesh.material.empty() || mesh.material[i] == mesh.material[j];
      if (same_material && dot(normal[i], normal[j]) >= min_cos) parent[find(i)] = find(j);
    }
  }
  SurfaceGroups g;
  g.group.assign(n, -1);
  std::map<size_t, int> id_of_root;
  for (size_t i = 0; i < n; ++i) {
    auto [it, fresh] = id_of_root.emplace(find(i), g.count);
    if (fresh) ++g.count;
    g.group[i] = it->second;
  }
  return g;
}

}  // namespace girtd
