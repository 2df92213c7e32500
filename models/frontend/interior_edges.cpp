#include "frontend/interior_edges.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace girtd {
namespace {

using Corner = std::pair<double, double>;

struct EdgeUse {
  size_t triangle;
  int edge;
  int side;  // which side of the edge (as keyed) the triangle's third corner lies on
};

int side_of(const Corner& a, const Corner& b, const Vertex& c) {
  const double cross = (b.first - a.first) * (c.y - a.second) - (b.second - a.second) * (c.x - a.first);
  return (cross > 0) - (cross < 0);
}

}  // namespace

void mark_interior_edges(std::vector<FrontTriangle>& frame) {
  std::map<std::tuple<int, Corner, Corner>, std::vector<EdgeUse>> uses;
  for (size_t k = 0; k < frame.size(); ++k) {
    Triangle& t = frame[k].tri;
    t.interior_edges = 0;
    if (t.surface < 0) continue;  // no surface, no neighbours of the same one
    for (int e = 0; e < 3; ++e) {
      Corner a{t.v[e].x, t.v[e].y}, b{t.v[(e + 1) % 3].x, t.v[(e + 1) % 3].y};
      if (b < a) std::swap(a, b);
      uses[{t.surface, a, b}].push_back({k, e, side_of(a, b, t.v[(e + 2) % 3])});
    }
  }
  for (const auto& [key, u] : uses) {
    if (u.size() != 2 || u[0].side * u[1].side >= 0) continue;  // not two neighbours side by side
    for (const EdgeUse& x : u) frame[x.triangle].tri.interior_edges |= static_cast<uint8_t>(1u << x.edge);
  }
}

}  // namespace girtd
