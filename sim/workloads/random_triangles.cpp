#include "workloads/random_triangles.hpp"

#include <cmath>

#include "config/params.hpp"
#include "girtd/design_constants.hpp"

namespace girtd {

Triangle random_triangle(std::mt19937& rng, double max_size) {
  std::uniform_real_distribution<double> u(0, 1);
  const double size = std::exp(std::log(0.5) + u(rng) * (std::log(max_size) - std::log(0.5)));
  static const double depth_max = Params::defaults().depth_max_mapped, colour_max = (1 << kColorOutBits) - 1;
  const double cx = u(rng) * kScreenWidth, cy = u(rng) * kScreenHeight;
  Triangle t;
  for (Vertex& v : t.v) {
    v.x = cx + (u(rng) - 0.5) * size;
    v.y = cy + (u(rng) - 0.5) * size;
    v.z = u(rng) * depth_max;
    v.r = u(rng) * colour_max;
    v.g = u(rng) * colour_max;
    v.b = u(rng) * colour_max;
    v.t = u(rng) < 0.3 ? u(rng) : 1.0;
  }
  return t;
}

}  // namespace girtd
