// A scene's models as placed in the world: each with its transform, its
// surface groups and their materials, and what its file says of the camera
// and the lights. The scene reader (JSON) and a bare model share it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frontend/rotation.hpp"
#include "frontend/surface_groups.hpp"
#include "frontend/world_frame.hpp"
#include "io/imported_model.hpp"

namespace girtd {

struct Transform {
  Vec3 scale{1, 1, 1}, rotate_deg, translate;
  // p' = translate + Rz Ry Rx (scale p): scale, then rotate about X, Y, Z, then move.
  Vec3 apply(Vec3 p) const {
    p = {p.x * scale.x, p.y * scale.y, p.z * scale.z};
    p = rotate_z(rotate_y(rotate_x(p, rotate_deg.x * kDegToRad), rotate_deg.y * kDegToRad), rotate_deg.z * kDegToRad);
    return p + translate;
  }
  // A direction: where the transform takes it, at unit length.
  Vec3 turn(Vec3 d) const { return normalized(apply(d) - apply({0, 0, 0})); }
  bool mirrors() const { return scale.x * scale.y * scale.z < 0; }
};

struct Instance {
  std::string name;
  std::shared_ptr<const ImportedModel> model;  // a file's, or a mesh given in the scene
  SurfaceGroups groups;
  std::vector<Surface> group_surface;  // each group's material
  bool corner_colours = false;         // the model's own (not when the scene names a material)
  Transform transform;
  const Mesh& mesh() const { return model->mesh; }
};

// A model file's camera as the scene places it.
struct PlacedCamera {
  Camera camera;
  std::optional<double> near;
};

// Each surface group's material: the scene's `chosen` one, else the file's,
// else the default. The scene's material replaces the file's corner colours too.
void choose_surfaces(Instance& in, const std::optional<Surface>& chosen);

// Polygons, surfaces of every instance placed with its transform.
void place(const std::vector<Instance>& instances, WorldFrame& w);

// Looks at the bounding box's centre from SceneDefaults::auto_view_direction,
// far enough that the bounding sphere fits the field of view.
void auto_frame(WorldFrame& w, double fov_deg, std::optional<double> focal);

// The lights a scene gets when neither it nor its files give any (SceneDefaults).
LightSet default_lights();

// The placed models' own lights, mapped together (model_lights.hpp), or nullopt.
std::optional<LightSet> file_lights(const std::vector<Instance>& instances, std::vector<std::string>& warnings);

// The camera named `name` among the placed models' files, or ("" ) the
// first perspective one; nullopt when there is none. A name that is not
// there is an error of `option`.
std::optional<PlacedCamera> file_camera(const std::vector<Instance>& instances, const std::string& name,
                                        const std::string& option, std::vector<std::string>& warnings);

}  // namespace girtd
