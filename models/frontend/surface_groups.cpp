#include "frontend/surface_groups.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <utility>

#include "common/parallel.hpp"
#include "frontend/vertex_normals.hpp"

namespace girtd {

SurfaceGroups surface_groups(const Mesh& mesh, double crease_deg, bool split_materials) {
  const size_t n = mesh.polygon_count();
  std::vector<size_t> parent(n);
  std::iota(parent.begin(), parent.end(), size_t{0});
  auto find = [&](size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  std::vector<Vec3> normal(n);
  parallel_for_each_index(n, [&](size_t i) {
    const CornerSpan poly = mesh.polygon(i);
    normal[i] = normalized(newell_normal(mesh.positions, poly.data, poly.size));
  });
  // Every polygon edge as (undirected edge, polygon), sorted: the polygons on
  // one edge follow each other, the first of them (its owner) leading.
  struct EdgeUse {
    uint64_t edge;
    uint64_t polygon;
    bool operator<(const EdgeUse& o) const { return edge != o.edge ? edge < o.edge : polygon < o.polygon; }
  };
  std::vector<EdgeUse> uses;
  uses.reserve(mesh.corners.size());
  for (size_t i = 0; i < n; ++i) {
    const CornerSpan poly = mesh.polygon(i);
    for (size_t k = 0; k < poly.size; ++k) {
      const uint32_t a = uint32_t(poly[k]), b = uint32_t(poly[(k + 1) % poly.size]);
      uses.push_back({uint64_t(std::min(a, b)) << 32 | std::max(a, b), i});
    }
  }
  parallel_sort_total(uses.begin(), uses.end(), std::less<EdgeUse>());
  // Allow rounding: a crease of exactly 90 deg joins 90-deg neighbours.
  const double min_cos = std::cos(crease_deg * M_PI / 180.0) - 1e-9;
  for (size_t at = 0; at < uses.size();) {
    const size_t j = uses[at].polygon;  // the edge's owner
    size_t next = at + 1;
    for (; next < uses.size() && uses[next].edge == uses[at].edge; ++next) {
      const size_t i = uses[next].polygon;
      // Two materials are two surfaces, however smooth the edge between them.
      const bool same_material = !split_materials || mesh.material.empty() || mesh.material[i] == mesh.material[j];
      if (same_material && dot(normal[i], normal[j]) >= min_cos) parent[find(i)] = find(j);
    }
    at = next;
  }
  // Numbered in order of first use: the numbering depends on the sets alone.
  SurfaceGroups g;
  g.group.assign(n, -1);
  std::vector<int> id_of_root(n, -1);
  for (size_t i = 0; i < n; ++i) {
    int& id = id_of_root[find(i)];
    if (id < 0) id = g.count++;
    g.group[i] = id;
  }
  return g;
}

}  // namespace girtd
