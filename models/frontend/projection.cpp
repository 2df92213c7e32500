#include "frontend/projection.hpp"

#include <algorithm>

namespace girtd {

double DepthMap::zp(double zs) const {
  if (!(zmax_ > zmin_)) return 0;
  const double v = zmax_ / (zmax_ - zmin_) * (1.0 - zmin_ / zs) * p_;
  return std::clamp(v, 0.0, p_);
}

}  // namespace girtd
