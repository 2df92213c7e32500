#include "workloads/random_triangles.hpp"

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
