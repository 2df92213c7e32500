#include "accuracy/llvmpipe_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace girtd {

namespace {

// Every triangle's edges and depth plane, and a grid of which triangles
// touch which 32 x 32 block, to explain a pixel without a scan of all.
class TriangleIndex {
 public:
  TriangleIndex(const std::vector<Triangle>& tris, int width, int height)
      : tris_(tris), cols_((width + 31) / 32), cells_(size_t(cols_) * ((height + 31) / 32)) {
    for (size_t i = 0; i < tris.size(); ++i) {
      double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
      for (const Vertex& v : tris[i].v)
        x0 = std::min(x0, v.x), y0 = std::min(y0, v.y), x1 = std::max(x1, v.x), y1 = std::max(y1, v.y);
      const int rows = int(cells_.size()) / cols_;
      for (int cy = std::max(0, int(y0 - 1) / 32); cy <= std::min(rows - 1, int(y1 + 1) / 32); ++cy)
        for (int cx = std::max(0, int(x0 - 1) / 32); cx <= std::min(cols_ - 1, int(x1 + 1) / 32); ++cx)
          cells_[size_t(cy) * cols_ + cx].push_back(i);
    }
  }
  // Whether an edge of a triangle near (x, y) passes within kEdgeTiePx,
  // and the depths of the triangles covering (x, y) exactly.
  void probe(int x, int y, bool& on_edge, std::vector<double>& depths) const {
    on_edge = false;
    depths.clear();
    for (size_t i : cells_[size_t(y / 32) * cols_ + x / 32]) {
      const auto& v = tris_[i].v;
      double d[3];
      for (int e = 0; e < 3; ++e) {
        const Vertex &a = v[e], &b = v[(e + 1) % 3];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        d[e] = len > 0 ? ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x)) / len : 0;
      }
      const bool inside = (d[0] >= 0 && d[1] >= 0 && d[2] >= 0) || (d[0] <= 0 && d[1] <= 0 && d[2] <= 0);
      for (double di : d) on_edge = on_edge || (std::abs(di) < kEdgeTiePx && near_box(v, x, y));
      if (inside) depths.push_back(depth_at(v, x, y));
    }
  }

 private:
  static bool near_box(const std::array<Vertex, 3>& v, double x, double y) {
    double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
    for (const Vertex& p : v) x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    return x >= x0 - kEdgeTiePx && x <= x1 + kEdgeTiePx && y >= y0 - kEdgeTiePx && y <= y1 + kEdgeTiePx;
  }
  static double depth_at(const std::array<Vertex, 3>& v, double x, double y) {
    const double det = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
    const double l1 = ((x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (y - v[0].y)) / det;
    const double l2 = ((v[1].x - v[0].x) * (y - v[0].y) - (x - v[0].x) * (v[1].y - v[0].y)) / det;
    return v[0].z + l1 * (v[1].z - v[0].z) + l2 * (v[2].z - v[0].z);
  }
  const std::vector<Triangle>& tris_;
  int cols_;
  std::vector<std::vector<size_t>> cells_;
};

}  // namespace

LlvmpipeComparison compare_with_llvmpipe(const std::vector<Triangle>& triangles, const RgbImage& a_rgb,
                                         const std::vector<uint16_t>& a_z, const LlvmpipeFrame& b, uint16_t z_clear) {
  LlvmpipeComparison c;
  c.image = compare_images(a_rgb, b.rgb);
  c.depth = compare_depth(a_z, b.z, z_clear);
  const TriangleIndex index(triangles, a_rgb.width, a_rgb.height);
  std::vector<double> depths;
  for (int y = 0; y < a_rgb.height; ++y)
    for (int x = 0; x < a_rgb.width; ++x) {
      const size_t i = size_t(y) * a_rgb.width + x;
      const bool in_a = a_z[i] != z_clear, in_b = b.z[i] != z_clear;
      bool colour_off = false;
      if (in_a && in_b)
        for (int ch = 0; ch < 3; ++ch) colour_off = colour_off || std::abs(int(a_rgb.rgb[3 * i + ch]) - int(b.rgb.rgb[3 * i + ch])) > 1;
      c.colour_over_1lsb += colour_off;
      if (in_a == in_b && !colour_off) continue;
      bool on_edge = false;
      index.probe(x, y, on_edge, depths);
      std::sort(depths.begin(), depths.end());
      const bool depth_tie = depths.size() >= 2 && depths[1] - depths[0] < kDepthTieUnits;
      if (on_edge) ++c.edge_ties;
      else if (depth_tie) ++c.depth_ties;
      else ++c.unexplained;
    }
  return c;
}

}  // namespace girtd
