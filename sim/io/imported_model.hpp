// What a model file holds beyond its polygons: its materials, cameras and
// lights, in the file's world space (each node's transform applied), as the
// importer read them. The scene reader decides what to use
// (models/frontend/README.md "Model files").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "frontend/mesh.hpp"
#include "frontend/world_frame.hpp"

namespace girtd {

struct ModelCamera {
  std::string name;
  Vec3 eye, forward{0, 0, -1}, up{0, 1, 0};  // forward and up: unit vectors
  double fov_deg = 40;       // across the (square) screen
  double near = 0;           // the file's near clip plane; 0: none given
  bool orthographic = false;  // GIRTD projects in perspective only
};

enum class ModelLightKind { kDirectional, kPoint, kSpot, kArea, kAmbient, kOther };

struct ModelLight {
  std::string name;
  ModelLightKind kind = ModelLightKind::kOther;
  Vec3 position;                   // point, spot and area lights
  Vec3 direction{0, 0, -1};        // unit: the way the light shines (directional, spot)
  double strength = 0;             // its brightest channel, in the file's own units
  bool coloured = false;           // its channels differ: GIRTD's lights are white
};

struct ImportedModel {
  Mesh mesh;
  // Mesh::material indexes this; nullopt: the file gives none (assimp's
  // filler, an OBJ without its library): the scene's default material.
  std::vector<std::optional<Surface>> materials;
  std::vector<ModelCamera> cameras;
  std::vector<ModelLight> lights;
};

}  // namespace girtd
