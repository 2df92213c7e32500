// What the front end receives for one frame: world-space polygons with
// surface ids, and the surfaces, lights and camera they are seen with. This is
// the `polygon` trace level (traces/FORMAT.md); scenes and models become it.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "frontend/mesh.hpp"
#include "frontend/vec3.hpp"

namespace girtd {

// CRE(i) sampled at i = 0, 15, ..., 90 degrees of incidence.
inline constexpr int kCreSteps = 7;
inline constexpr double kCreStepDeg = 15.0;

// The specular exponent's range, the thesis' n = 1 (matte) .. 200 (mirror).
inline constexpr double kMinSpecularExponent = 1;
inline constexpr double kMaxSpecularExponent = 200;

// A surface's material (§3 lighting). Polygons of one surface share vertex
// normals; a vertex on two surfaces keeps one normal per surface.
struct Surface {
  double r = 200, g = 200, b = 200;  // diffuse reflectance as a colour, 0..255
  std::array<double, kCreSteps> cre{};  // specular reflectance 0..1 per 15 deg
  double n = 1;                         // specular exponent, 1 (matte) .. 200 (mirror)
  double t_min = 0, t_max = 0;          // Tf = Tmin + (Tmax - Tmin)|N.E|; opaque 0, 0
};

struct DirectionalLight {
  Vec3 toward;           // unit vector toward the light (world space)
  double intensity = 1;  // If
};

struct LightSet {
  double ambient = 0;  // Id
  std::vector<DirectionalLight> directional;
};

// Camera centre and its axes in world coordinates: camera space is
// Xs = (P - centre).right, Ys = (P - centre).up, Zs = (P - centre).forward.
struct Camera {
  Vec3 centre;
  Vec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, -1};
  double d_over_s = 1;  // D/S of Xp = Xs/Zs * D/S: 1 / tan(half field of view)
};

struct WorldPolygon {
  int surface = 0;
  std::vector<Vec3> p;  // counter-clockwise seen from the front (outside)
  int source_line = 0;  // where it came from, for error messages
  // Empty, or one per corner: the corner's diffuse colour in place of the
  // surface's R, G, B (a model's vertex colours or texture stand-in).
  std::vector<CornerColour> colour;
};

// Consecutive polygons culled together (a scene's model): config
// culling.objects tests their bounding sphere against the view volume.
struct WorldObject {
  size_t first = 0;  // index of its first polygon
  size_t count = 0;
};

struct WorldFrame {
  Camera camera;
  LightSet lights;
  std::vector<Surface> surfaces;
  double focal_distance = 0;  // C: the depth clip keeps Zs > C
  bool cull_back_faces = false;
  std::vector<WorldPolygon> polygons;
  std::vector<WorldObject> objects;  // cover `polygons` in order; empty: the frame is one object
};

// The frame's objects that hold polygons, or the whole frame as one when it
// names none. The readers make them cover the polygons in order.
inline std::vector<WorldObject> frame_objects(const WorldFrame& w) {
  std::vector<WorldObject> out;
  size_t next = 0;
  for (const WorldObject& o : (w.objects.empty() ? std::vector<WorldObject>{{0, w.polygons.size()}} : w.objects)) {
    if (o.first != next) throw std::logic_error("WorldFrame::objects do not cover the polygons in order");
    next += o.count;
    if (o.count > 0) out.push_back(o);
  }
  if (next != w.polygons.size()) throw std::logic_error("WorldFrame::objects do not cover every polygon");
  return out;
}

}  // namespace girtd
