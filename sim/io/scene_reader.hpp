// Scene files (JSON, traces/FORMAT.md "Scene files") and bare model files
// become a polygon-level Trace: per frame, world-space polygons with surface
// ids, the surfaces, lights and camera. Unknown keys are errors; every
// problem is an InputError "FILE:LINE: what".
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "config/params.hpp"
#include "frontend/vec3.hpp"
#include "frontend/world_frame.hpp"
#include "io/trace.hpp"

namespace girtd {

// Defaults for what a scene leaves out (and for a bare model), documented in
// models/frontend/README.md.
struct SceneDefaults {
  static constexpr double kFovDeg = 40.0;
  static constexpr double kFocalDistance = 0.1;      // scene units, explicit camera
  static constexpr double kAutoFocalFraction = 0.01;  // auto camera: C = distance / 100
  static constexpr double kAutoMargin = 1.05;         // auto camera: bounding sphere fills 1/1.05 of the view
  static Vec3 auto_view_direction() { return {0.6, 0.45, 1.0}; }  // from the model's centre toward the eye
  static constexpr double kAmbient = 0.25;
  static Vec3 light_toward() { return {0.3, 1.0, 0.6}; }  // above, a little right, in front
  static constexpr double kLightIntensity = 0.75;
  static Surface material();  // light grey, CRE 0.30 .. 0.80, n = 20, opaque
};

// A scene places every frame's polygons before the front end runs, so frames
// x polygon corners is capped: 30 M corners hold about 1.2 GB.
inline constexpr uint64_t kMaxSceneCorners = 30000000;

Trace read_scene(const std::string& path, const Params& params);

// A scene given as a document rather than a file (the library's
// RenderRequest::scene): the same keys, "mesh" models included; errors name
// `name` and the key ("NAME: \"models/0/mesh\" ..."); model paths are relative
// to the working directory.
Trace read_scene_document(const nlohmann::json& document, const std::string& name, const Params& params);

// A bare model: auto-framed camera, default light and material, one frame.
Trace scene_from_model(const std::string& path, const Params& params);

}  // namespace girtd
