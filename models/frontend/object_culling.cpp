#include "frontend/object_culling.hpp"

#include <algorithm>

#include <glm/common.hpp>

#include "frontend/view_transform.hpp"

namespace girtd {

BoundingSphere bounding_sphere(const std::vector<WorldPolygon>& polygons, const WorldObject& object) {
  Vec3 lo{1e300, 1e300, 1e300}, hi = lo * -1.0;
  for (size_t i = object.first; i < object.first + object.count; ++i)
    for (const Vec3& p : polygons[i].p) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  BoundingSphere s;
  if (object.count == 0) return s;
  s.centre = (lo + hi) * 0.5;
  for (size_t i = object.first; i < object.first + object.count; ++i)
    for (const Vec3& p : polygons[i].p) s.radius = std::max(s.radius, length(p - s.centre));
  return s;
}

ViewVolume::ViewVolume(const Camera& camera, double focal, ScreenMap screen, const Window& window, double margin_px)
    : camera_(camera), focal_(focal) {
  // Xp = Xs/Zs D/S maps to x = (W - 1)/2 (1 + Xp), and Yp to y = (H - 1)/2 (1 - Yp):
  // the widened window's bounds in Xp, Yp.
  const double ds = camera.d_over_s;
  const double xp_lo = 2 * (window.x0 - margin_px) / (screen.width - 1) - 1;
  const double xp_hi = 2 * (window.x1 + margin_px) / (screen.width - 1) - 1;
  const double yp_lo = 1 - 2 * (window.y1 + margin_px) / (screen.height - 1);
  const double yp_hi = 1 - 2 * (window.y0 - margin_px) / (screen.height - 1);
  // Inside: Xs D/S <= xp_hi Zs, Xs D/S >= xp_lo Zs, and the same for Ys.
  sides_ = {normalized(Vec3{ds, 0, -xp_hi}), normalized(Vec3{-ds, 0, xp_lo}), normalized(Vec3{0, ds, -yp_hi}),
            normalized(Vec3{0, -ds, yp_lo})};
}

bool ViewVolume::misses(const BoundingSphere& sphere) const {
  const Vec3 c = to_camera_space(camera_, sphere.centre);
  // An allowance for rounding and for camera axes orthonormal only within
  // 1e-6 (a trace's camera): never cull what touches the volume.
  const double r = sphere.radius + 1e-5 * (length(c) + sphere.radius) + 1e-12;
  if (c.z + r <= focal_) return true;  // wholly at Zs <= C: the depth clip would drop every polygon
  return std::any_of(sides_.begin(), sides_.end(), [&](const Vec3& n) { return dot(n, c) > r; });
}

bool ViewVolume::misses(const std::vector<Vec3>& points) const {
  // One pass: which faces every point so far lies outside of.
  bool behind = true;
  std::array<bool, 4> beyond{true, true, true, true};
  for (const Vec3& p : points) {
    const Vec3 c = to_camera_space(camera_, p);
    behind = behind && c.z <= focal_;
    for (size_t k = 0; k < sides_.size(); ++k) beyond[k] = beyond[k] && dot(sides_[k], c) > 0;
  }
  return behind || std::any_of(beyond.begin(), beyond.end(), [](bool b) { return b; });
}

}  // namespace girtd
