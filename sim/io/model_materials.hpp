// A model file's materials as GIRTD surfaces, and its textures' stand-in.
// Runs in the importer's child (textures are decoded there, inside its
// limits). What cannot be shown is named once per kind in `warnings()`.
//
// A Gouraud machine interpolates colours between vertices; it has no texture
// memory. A texture therefore stands in as its mean colour over each face
// (sampled over the face's UV polygon), multiplying the material's colour as
// OBJ's Kd x map_Kd and glTF's base colour factor x texture do. The picture
// keeps the texture's overall hue per face and loses its detail: models/
// frontend/README.md "Textures" weighs this against the alternatives.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <assimp/scene.h>

#include "frontend/mesh.hpp"
#include "frontend/world_frame.hpp"

namespace girtd {

// Materials the importer made up although the file names them: an OBJ's
// usemtl that no library defines (`names`), or every one when the library
// could not be read (`all`).
struct MadeUpMaterials {
  std::set<std::string> names;
  bool all = false;
};

class ModelLook {
 public:
  ModelLook(const aiScene& scene, const std::string& model_path, const MadeUpMaterials& made_up = {});

  // One per aiMaterial; nullopt for a material the importer made up (the
  // file has none): the default material is drawn.
  const std::vector<std::optional<Surface>>& surfaces() const { return surfaces_; }

  // The mean of material `m`'s diffuse texture over the polygon whose corners
  // have texture coordinates `uv` (0..1 a channel), or nullopt when it has
  // none or it cannot be read (warned).
  std::optional<CornerColour> texture_mean(unsigned m, const std::vector<aiVector3D>& uv);
  bool has_texture(unsigned m) const { return m < texture_of_.size() && !texture_of_[m].empty(); }

  // "what" lines, each kind once, for the caller to prefix with the file's name.
  std::vector<std::string> warnings() const;

 private:
  struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;  // row 0 at the top
  };
  // 8192 x 8192: 192 MiB as decoded, twice that while it is copied.
  static constexpr uint64_t kMaxTexels = uint64_t(1) << 26;
  const Image* image(const std::string& name);
  void note(const std::string& what) { notes_[what]++; }

  const aiScene& scene_;
  std::string folder_;
  std::vector<std::optional<Surface>> surfaces_;
  std::vector<std::string> texture_of_;  // per material: its diffuse texture's name, or ""
  std::map<std::string, std::optional<Image>> images_;
  std::map<std::string, int> notes_;
  std::vector<std::string> unreadable_, too_large_;  // texture names, each once (images_ caches)
};

}  // namespace girtd
