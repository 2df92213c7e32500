// §3 view transform: world -> camera space, [Xs Ys Zs] = (P - centre) x T,
// T's columns the camera's right, up and forward axes. Zs is the depth
// (positive in front), Ys up; the projection flips y for the screen.
//
// Two ways to place the camera (models/frontend/README.md):
// - look-at: eye, target, up;
// - the thesis' centre + three view angles, which it leaves without a
//   convention. Here: the camera at yaw = pitch = roll = 0 looks along world
//   -Z with up +Y; its axes are rotated by Ry(yaw) Rx(pitch) Rz(roll)
//   (roll applied first, about the view axis; right-handed rotations, so yaw > 0
//   turns left, pitch > 0 looks up, roll > 0 turns the camera counter-clockwise
//   as seen from behind it).
#pragma once

#include <optional>

#include "frontend/world_frame.hpp"

namespace girtd {

Vec3 to_camera_space(const Camera& c, Vec3 world);

// D/S for a full field of view across the square projection plane.
double d_over_s_for_fov(double fov_deg);

// nullopt when eye == target or up is parallel to the view direction.
std::optional<Camera> camera_look_at(Vec3 eye, Vec3 target, Vec3 up, double fov_deg);
Camera camera_from_angles(Vec3 centre, double yaw_deg, double pitch_deg, double roll_deg, double fov_deg);

}  // namespace girtd
