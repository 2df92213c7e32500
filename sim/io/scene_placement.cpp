#include "io/scene_placement.hpp"

#include <algorithm>
#include <cmath>

#include "common/input_error.hpp"
#include "frontend/view_transform.hpp"
#include "io/model_lights.hpp"
#include "io/scene_defaults.hpp"

namespace girtd {

namespace {

// The centre of the box around `points` (each a Vec3 handed to `visit`'s callback).
template <class Visit>
Vec3 box_centre(Visit visit) {
  Vec3 lo{1e300, 1e300, 1e300}, hi = lo * -1.0;
  visit([&](const Vec3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  });
  return (lo + hi) * 0.5;
}

}  // namespace

void choose_surfaces(Instance& in, const std::optional<Surface>& chosen) {
  const Mesh& mesh = in.mesh();
  in.group_surface.assign(size_t(in.groups.count), chosen ? *chosen : SceneDefaults::material());
  in.corner_colours = !chosen && !mesh.corner_colour.empty();
  if (chosen || mesh.material.empty()) return;
  for (size_t i = 0; i < mesh.polygon_count(); ++i)  // a group holds one material (surface_groups.hpp)
    if (const std::optional<Surface>& m = in.model->materials.at(size_t(mesh.material[i])))
      in.group_surface[size_t(in.groups.group[i])] = *m;
}

void place(const std::vector<Instance>& instances, WorldFrame& w) {
  for (const Instance& in : instances) {
    const Mesh& mesh = in.mesh();
    const int base = static_cast<int>(w.surfaces.size());
    w.surfaces.insert(w.surfaces.end(), in.group_surface.begin(), in.group_surface.end());
    std::vector<Vec3> moved;
    moved.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) moved.push_back(in.transform.apply(p));
    w.objects.push_back({w.polygons.size(), mesh.polygon_count()});
    w.polygons.reserve(w.polygons.size() + mesh.polygon_count());
    for (size_t i = 0; i < mesh.polygon_count(); ++i) {
      WorldPolygon poly;
      poly.surface = base + in.groups.group[i];
      const CornerSpan corners = mesh.polygon(i);
      poly.p.reserve(corners.size);
      for (int k : corners) poly.p.push_back(moved[static_cast<size_t>(k)]);
      if (in.corner_colours)
        poly.colour.assign(mesh.corner_colour.begin() + std::ptrdiff_t(mesh.first[i]),
                           mesh.corner_colour.begin() + std::ptrdiff_t(mesh.first[i + 1]));
      if (in.transform.mirrors()) {  // keep the front counter-clockwise
        std::reverse(poly.p.begin(), poly.p.end());
        std::reverse(poly.colour.begin(), poly.colour.end());
      }
      w.polygons.push_back(std::move(poly));
    }
  }
}

void auto_frame(WorldFrame& w, double fov_deg, std::optional<double> focal) {
  const Vec3 centre = box_centre([&](auto&& see) {
    for (const WorldPolygon& poly : w.polygons)
      for (const Vec3& p : poly.p) see(p);
  });
  double radius = 0;
  for (const WorldPolygon& poly : w.polygons)
    for (const Vec3& p : poly.p) radius = std::max(radius, length(p - centre));
  if (radius == 0) radius = 1;
  const double dist = radius / std::sin(0.5 * fov_deg * M_PI / 180.0) * SceneDefaults::kAutoMargin;
  const Vec3 eye = centre + normalized(SceneDefaults::auto_view_direction()) * dist;
  w.camera = *camera_look_at(eye, centre, {0, 1, 0}, fov_deg);  // the view direction is never vertical
  w.focal_distance = focal ? *focal : dist * SceneDefaults::kAutoFocalFraction;
}

LightSet default_lights() {
  LightSet l;
  l.ambient = SceneDefaults::kAmbient;
  l.directional.push_back({normalized(SceneDefaults::light_toward()), SceneDefaults::kLightIntensity});
  return l;
}

std::optional<LightSet> file_lights(const std::vector<Instance>& instances, std::vector<std::string>& warnings) {
  std::vector<ModelLight> all;
  for (const Instance& in : instances)
    for (ModelLight l : in.model->lights) {
      l.position = in.transform.apply(l.position);
      l.direction = in.transform.turn(l.direction);
      all.push_back(l);
    }
  if (all.empty()) return std::nullopt;
  const Vec3 centre = box_centre([&](auto&& see) {
    for (const Instance& in : instances)
      for (const Vec3& p : in.mesh().positions) see(in.transform.apply(p));
  });
  return map_model_lights(all, centre, instances.size() == 1 ? instances[0].name : "the scene's models", warnings);
}

std::optional<PlacedCamera> file_camera(const std::vector<Instance>& instances, const std::string& name,
                                        const std::string& option, std::vector<std::string>& warnings) {
  std::vector<std::string> seen;
  std::string passed_over;  // orthographic cameras, named in one warning
  auto warn_passed_over = [&] {
    if (!passed_over.empty())
      warnings.push_back("orthographic cameras passed over (GIRTD projects in perspective only): " + passed_over);
  };
  for (const Instance& in : instances)
    for (const ModelCamera& c : in.model->cameras) {
      seen.push_back(c.name);
      if (!name.empty() && c.name != name) continue;
      if (c.orthographic) {
        if (!name.empty()) throw InputError(option, 0, "camera \"" + name + "\" is orthographic: GIRTD projects in perspective only");
        passed_over += (passed_over.empty() ? "" : ", ") + in.name + " \"" + c.name + "\"";
        continue;
      }
      ModelCamera placed = c;
      placed.eye = in.transform.apply(c.eye);
      placed.forward = in.transform.turn(c.forward);
      placed.up = in.transform.turn(c.up);
      const std::optional<Camera> cam = map_model_camera(placed);
      if (!cam) {
        if (!name.empty()) throw InputError(option, 0, "camera \"" + name + "\" has no view direction");
        continue;
      }
      warn_passed_over();
      std::optional<double> near;
      if (c.near > 0) {
        // The scene's own range of focal_distance, so that a dump replays.
        near = std::clamp(c.near, kMinFocalDistance, kMaxFocalDistance);
        if (*near != c.near)
          warnings.push_back(in.name + ": camera \"" + c.name + "\"'s near plane " + std::to_string(c.near) +
                             " taken as " + std::to_string(*near) + " (the focal distance's range)");
      }
      return PlacedCamera{*cam, near};
    }
  warn_passed_over();
  if (name.empty()) return std::nullopt;
  std::string list;
  for (const std::string& n : seen) list += (list.empty() ? "" : ", ") + ("\"" + n + "\"");
  throw InputError(option, 0, "no camera named \"" + name + "\" in the model" +
                                  (seen.empty() ? " (it has no cameras)" : " (its cameras: " + list + ")"));
}

}  // namespace girtd
