#include "frontend/view_transform.hpp"

#include <cmath>

#include "frontend/rotation.hpp"

namespace girtd {

Vec3 to_camera_space(const Camera& c, Vec3 world) {
  const Vec3 d = world - c.centre;
  return {dot(d, c.right), dot(d, c.up), dot(d, c.forward)};
}

double d_over_s_for_fov(double fov_deg) { return 1.0 / std::tan(0.5 * fov_deg * kDegToRad); }

std::optional<Camera> camera_look_at(Vec3 eye, Vec3 target, Vec3 up, double fov_deg) {
  Camera c;
  c.centre = eye;
  c.forward = normalized(target - eye);
  c.right = normalized(cross(c.forward, up));
  if (length(c.forward) == 0 || length(c.right) < 0.5) return std::nullopt;
  c.up = cross(c.right, c.forward);
  c.d_over_s = d_over_s_for_fov(fov_deg);
  return c;
}

Camera camera_from_angles(Vec3 centre, double yaw_deg, double pitch_deg, double roll_deg, double fov_deg) {
  auto rotate = [&](Vec3 v) {
    return rotate_y(rotate_x(rotate_z(v, roll_deg * kDegToRad), pitch_deg * kDegToRad), yaw_deg * kDegToRad);
  };
  Camera c;
  c.centre = centre;
  c.right = rotate({1, 0, 0});
  c.up = rotate({0, 1, 0});
  c.forward = rotate({0, 0, -1});
  c.d_over_s = d_over_s_for_fov(fov_deg);
  return c;
}

}  // namespace girtd
