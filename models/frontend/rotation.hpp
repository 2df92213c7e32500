// Right-handed rotations about the world axes (angle in radians, positive =
// counter-clockwise looking from the axis' positive end toward the origin).
// One definition for the three-angle camera (view_transform) and for the
// scene's model transforms (sim/io/scene_reader).
#pragma once

#include <cmath>

#include "frontend/vec3.hpp"

namespace girtd {

inline constexpr double kDegToRad = M_PI / 180.0;

inline Vec3 rotate_x(Vec3 v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
}

inline Vec3 rotate_y(Vec3 v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

inline Vec3 rotate_z(Vec3 v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

}  // namespace girtd
