#include "io/model_lights.hpp"

#include <algorithm>
#include <map>

#include "frontend/view_transform.hpp"
#include "io/scene_defaults.hpp"
#include "io/trace.hpp"

namespace girtd {

std::optional<LightSet> map_model_lights(const std::vector<ModelLight>& lights, Vec3 scene_centre,
                                         const std::string& who, std::vector<std::string>& warnings) {
  std::map<std::string, int> notes;  // each kind of approximation once, in a stable order
  std::vector<DirectionalLight> mapped;
  std::vector<double> strength;
  for (const ModelLight& l : lights) {
    if (l.kind == ModelLightKind::kAmbient) {
      notes["ambient lights are not taken: the ambient term stays the default 0.25"]++;
      continue;
    }
    if (l.strength <= 0) continue;  // a black light adds nothing
    Vec3 toward;
    if (l.kind == ModelLightKind::kDirectional) {
      toward = l.direction * -1.0;
    } else {
      toward = l.position - scene_centre;
      if (l.kind == ModelLightKind::kSpot) notes["spot lights' cones are not modelled: each shines as a directional light from its position"]++;
      if (l.kind == ModelLightKind::kArea) notes["area lights are drawn as directional lights from their centre"]++;
      if (l.kind == ModelLightKind::kOther) notes["lights of an unknown kind are drawn as directional lights from their position"]++;
    }
    if (!finite(toward) || length(toward) == 0) {
      notes["a light with no direction toward the scene (at its centre, or pointing nowhere) is left out"]++;
      continue;
    }
    if (l.coloured) notes["light colours are dropped: GIRTD's lights are white (intensity from the brightest channel)"]++;
    mapped.push_back({normalized(toward), 0});
    strength.push_back(l.strength);
  }
  // A polygon dump must replay: the brightest kMaxTraceLights are kept.
  if (mapped.size() > static_cast<size_t>(kMaxTraceLights)) {
    std::vector<size_t> order(mapped.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return strength[a] > strength[b]; });
    order.resize(kMaxTraceLights);
    std::sort(order.begin(), order.end());
    std::vector<DirectionalLight> kept_lights;
    std::vector<double> kept_strength;
    for (size_t i : order) kept_lights.push_back(mapped[i]), kept_strength.push_back(strength[i]);
    warnings.push_back(who + ": " + std::to_string(mapped.size()) + " lights: the " + std::to_string(kMaxTraceLights) +
                       " brightest are drawn (a polygon trace holds at most " + std::to_string(kMaxTraceLights) + ")");
    mapped = std::move(kept_lights);
    strength = std::move(kept_strength);
  }
  double total = 0;
  for (double s : strength) total += s;
  for (size_t i = 0; i < mapped.size(); ++i) mapped[i].intensity = SceneDefaults::kLightIntensity * strength[i] / total;
  for (const auto& [what, count] : notes) warnings.push_back(who + ": " + what);
  if (mapped.empty()) {
    if (!lights.empty()) warnings.push_back(who + ": none of its lights can be used: the default light is drawn");
    return std::nullopt;
  }
  LightSet set;
  set.ambient = SceneDefaults::kAmbient;
  set.directional = std::move(mapped);
  return set;
}

std::optional<Camera> map_model_camera(const ModelCamera& c) {
  if (length(c.forward) == 0) return std::nullopt;
  const double fov = std::clamp(c.fov_deg, 1.0, 170.0);
  if (std::optional<Camera> cam = camera_look_at(c.eye, c.eye + c.forward, c.up, fov)) return cam;
  // An up vector along the view: any other up keeps the view direction.
  for (const Vec3& up : {Vec3{0, 1, 0}, Vec3{0, 0, 1}})
    if (std::optional<Camera> cam = camera_look_at(c.eye, c.eye + c.forward, up, fov)) return cam;
  return std::nullopt;
}

}  // namespace girtd
