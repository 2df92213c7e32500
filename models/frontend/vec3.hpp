// The front end's 3-vector of doubles (world and camera space): GLM's dvec3,
// zero-initialized, with GLM's dot, cross and length (found by argument-
// dependent lookup). Two helpers GLM does not have follow.
#pragma once

#ifndef GLM_FORCE_CTOR_INIT  // models/CMakeLists.txt defines it for every file
#error "GLM_FORCE_CTOR_INIT must be defined (Vec3{} is the zero vector the stages expect)"
#endif
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace girtd {

using Vec3 = glm::dvec3;

// Zero stays zero (a degenerate polygon has no normal), where glm::normalize
// would divide by zero.
inline Vec3 normalized(Vec3 a) {
  const double l = glm::length(a);
  return l > 0 ? a * (1.0 / l) : Vec3{};
}
inline bool finite(Vec3 a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

}  // namespace girtd
