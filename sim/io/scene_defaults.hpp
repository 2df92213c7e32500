// What a scene, a bare model or a model file's material leaves out.
#pragma once

#include "frontend/vec3.hpp"
#include "frontend/world_frame.hpp"

namespace girtd {

// A scene's focal distance C (scene units), as a trace's `focal` takes it too.
inline constexpr double kMinFocalDistance = 1e-9;
inline constexpr double kMaxFocalDistance = 1e12;

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

inline Surface SceneDefaults::material() {
  Surface s;
  s.r = s.g = s.b = 200;
  s.cre = {0.30, 0.30, 0.31, 0.33, 0.38, 0.50, 0.80};
  s.n = 20;
  return s;
}

}  // namespace girtd
