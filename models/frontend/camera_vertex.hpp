// A lit vertex in camera space: what the depth clip cuts and the projection maps.
#pragma once

#include "frontend/vec3.hpp"

namespace girtd {

struct CameraVertex {
  Vec3 s;                      // Xs, Ys, Zs
  double r = 0, g = 0, b = 0;  // lit colour 0..255
  double t = 1;                // opacity
  bool created = false;        // made by the depth clip at Zs = C
};

}  // namespace girtd
