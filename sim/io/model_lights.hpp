// A model file's cameras and lights on GIRTD's camera and lighting model
// (sim/io/README.md "Cameras and lights").
//
// GIRTD lights are white directional lights of intensity 0..16 and an ambient
// term. A directional light keeps its direction; a point, spot or area light
// becomes a directional light from its position toward the scene's centre.
// Intensities, whatever the file's units and falloff, are normalised so that
// together they give the default light's 0.75 (with the default ambient
// 0.25, a white surface facing every light at once just reaches 255): no
// light washes the scene out. No ambient term is taken from the file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "frontend/world_frame.hpp"
#include "io/imported_model.hpp"

namespace girtd {

// The lights mapped, or nullopt when none can be (the caller's default then).
// What is approximated is appended to `warnings` once per kind, as "WHO: what".
std::optional<LightSet> map_model_lights(const std::vector<ModelLight>& lights, Vec3 scene_centre,
                                         const std::string& who, std::vector<std::string>& warnings);

// The camera, or nullopt when its axes say nothing (a zero direction).
std::optional<Camera> map_model_camera(const ModelCamera& camera);

}  // namespace girtd
