// Right-handed rotations about the world axes (angle in radians, positive =
// counter-clockwise looking from the axis' positive end toward the origin):
// GLM's rotateX/Y/Z. One definition for the three-angle camera
// (view_transform) and for the scene's model transforms (sim/io/scene_reader).
#pragma once

#include "frontend/vec3.hpp"  // first: it checks the GLM definitions

#include <glm/gtx/rotate_vector.hpp>  // gtx (GLM_ENABLE_EXPERIMENTAL): stable since GLM 0.9.5

namespace girtd {

inline constexpr double kDegToRad = M_PI / 180.0;

inline Vec3 rotate_x(Vec3 v, double a) { return glm::rotateX(v, a); }
inline Vec3 rotate_y(Vec3 v, double a) { return glm::rotateY(v, a); }
inline Vec3 rotate_z(Vec3 v, double a) { return glm::rotateZ(v, a); }

}  // namespace girtd
