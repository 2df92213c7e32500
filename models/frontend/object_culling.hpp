// Bounding-sphere culling of whole objects (seed 003 §5: "it eliminates
// whole objects with very few operations"), in front of lighting: an
// object whose sphere lies wholly outside one face of the view volume has no
// pixel to draw, so none of its polygons is lit, transformed or clipped.
// The view volume is the window widened by a margin (the AA fringe and a
// pixel for rounding) seen from the eye, cut at the depth clip's Zs = C.
#pragma once

#include <array>
#include <vector>

#include "common/types.hpp"
#include "frontend/projection.hpp"
#include "frontend/world_frame.hpp"

namespace girtd {

struct BoundingSphere {
  Vec3 centre;
  double radius = 0;
};

// Centre of the bounding box, radius to the farthest corner (the thesis'
// database would store it with the model; here it is found per frame).
BoundingSphere bounding_sphere(const std::vector<WorldPolygon>& polygons, const WorldObject& object);

class ViewVolume {
 public:
  ViewVolume() = default;
  // Points drawn inside `window` widened by `margin_px` on every side, in
  // front of the clip plane Zs = `focal`.
  ViewVolume(const Camera& camera, double focal, ScreenMap screen, const Window& window, double margin_px);
  // True when the sphere (world space) lies wholly outside one face.
  bool misses(const BoundingSphere& sphere) const;
  // True when every point (world space) lies outside one face (the same
  // face for all): nothing drawn from them can reach the window.
  bool misses(const std::vector<Vec3>& points) const;

 private:
  Camera camera_;
  double focal_ = 0;
  std::array<Vec3, 4> sides_{};  // unit normals through the eye, pointing out of the volume
};

}  // namespace girtd
