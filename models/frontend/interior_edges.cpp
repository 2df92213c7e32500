#include "frontend/interior_edges.hpp"

#include <stdexcept>
#include <tuple>
#include <utility>

#include "common/equal_keys.hpp"

namespace girtd {
namespace {

using Corner = std::pair<double, double>;

int side_of(const Corner& a, const Corner& b, const Vertex& c) {
  const double cross = (b.first - a.first) * (c.y - a.second) - (b.second - a.second) * (c.x - a.first);
  return (cross > 0) - (cross < 0);
}

// Edge e of a triangle with its ends in a fixed order, so both triangles on
// it name it alike.
std::pair<Corner, Corner> ends(const Triangle& t, int e) {
  Corner a{t.v[e].x, t.v[e].y}, b{t.v[(e + 1) % 3].x, t.v[(e + 1) % 3].y};
  if (b < a) std::swap(a, b);
  return {a, b};
}

}  // namespace

void mark_interior_edges(std::vector<Triangle>& frame) {
  // Every edge of a triangle with a surface, as 4 x triangle + edge.
  if (frame.size() >= (size_t{1} << 30)) throw std::length_error("mark_interior_edges: 2^30 triangles or more");
  std::vector<uint32_t> edge_of;
  edge_of.reserve(3 * frame.size());
  for (size_t k = 0; k < frame.size(); ++k) {
    Triangle& t = frame[k];
    t.interior_edges = 0;
    if (t.surface < 0) continue;  // no surface, no neighbours of the same one
    for (uint32_t e = 0; e < 3; ++e) edge_of.push_back(uint32_t(4 * k) + e);
  }
  const auto key_of = [&](size_t i) {
    const Triangle& t = frame[edge_of[i] / 4];
    const auto [a, b] = ends(t, int(edge_of[i] % 4));
    return std::make_tuple(t.surface, same_zero(a.first), same_zero(a.second), same_zero(b.first), same_zero(b.second));
  };
  for_each_equal_key(edge_of.size(), key_of, [&](const uint32_t* use, size_t n) {
    if (n != 2) return;  // not two neighbours
    int side[2];
    for (int u = 0; u < 2; ++u) {
      const Triangle& t = frame[edge_of[use[u]] / 4];
      const int e = int(edge_of[use[u]] % 4);
      const auto [a, b] = ends(t, e);
      side[u] = side_of(a, b, t.v[(e + 2) % 3]);
    }
    if (side[0] * side[1] >= 0) return;  // not side by side
    for (int u = 0; u < 2; ++u)
      frame[edge_of[use[u]] / 4].interior_edges |= static_cast<uint8_t>(1u << (edge_of[use[u]] % 4));
  });
}

}  // namespace girtd
