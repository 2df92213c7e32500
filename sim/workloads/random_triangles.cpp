#include "workloads/random_triangles.hpp"

#include <algorithm>
#include <cmath>

namespace girtd {

Triangle random_triangle(std::mt19937& rng, double max_size) {
  std::uniform_real_distribution<double> u(0, 1);
  const double size = std::exp(std::log(0.5) + u(rng) * (std::log(max_size) - std::log(0.5)));
  const double cx = u(rng) * 1024, cy = u(rng) * 1024;
  Triangle t;
  for (Vertex& v : t.v) {
    v.x = cx + (u(rng) - 0.5) * size;
    v.y = cy + (u(rng) - 0.5) * size;
    v.z = u(rng) * 65534;
    v.r = u(rng) * 255;
    v.g = u(rng) * 255;
    v.b = u(rng) * 255;
    v.t = u(rng) < 0.3 ? u(rng) : 1.0;
  }
  return t;
}

}  // namespace girtd

namespace girtd {

namespace {

double smallest_angle_deg(const Triangle& t) {
  double smallest = 180;
  for (int i = 0; i < 3; ++i) {
    const Vertex &a = t.v[i], &b = t.v[(i + 1) % 3], &c = t.v[(i + 2) % 3];
    const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
    const double cosine = (ux * vx + uy * vy) / std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy));
    smallest = std::min(smallest, std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / M_PI);
  }
  return smallest;
}

}  // namespace

Triangle random_opaque_triangle(std::mt19937& rng, double area, int width, int height) {
  std::uniform_real_distribution<double> u(0, 1);
  Triangle t;
  for (;;) {
    for (Vertex& v : t.v) {
      v.x = u(rng);
      v.y = u(rng);
    }
    if (smallest_angle_deg(t) >= 15) break;
  }
  const Vertex &a = t.v[0], &b = t.v[1], &c = t.v[2];
  const double unit_area = std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2;
  const double scale = std::sqrt(area / unit_area);
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (Vertex& v : t.v) {
    v.x *= scale;
    v.y *= scale;
    x0 = std::min(x0, v.x), y0 = std::min(y0, v.y), x1 = std::max(x1, v.x), y1 = std::max(y1, v.y);
  }
  const double dx = 1 + u(rng) * (width - 2 - (x1 - x0)) - x0, dy = 1 + u(rng) * (height - 2 - (y1 - y0)) - y0;
  for (Vertex& v : t.v) {
    v.x = std::round((v.x + dx) * 256) / 256;
    v.y = std::round((v.y + dy) * 256) / 256;
    v.z = u(rng) * 65534;
    v.r = u(rng) * 255;
    v.g = u(rng) * 255;
    v.b = u(rng) * 255;
    v.t = 1.0;
  }
  return t;
}

}  // namespace girtd
