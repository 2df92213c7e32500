#include "io/model_materials.hpp"

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <stb/stb_image.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>

#include "io/scene_defaults.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

float unit(float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f; }

// A material's colour, shininess and opacity (sim/io/README.md "Materials").
Surface surface_of(const aiMaterial& m, std::map<std::string, int>& notes) {
  Surface s = SceneDefaults::material();  // what the file does not say
  aiColor4D c;
  double alpha = 1;
  if (m.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS || m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) {
    s.r = 255.0 * unit(c.r), s.g = 255.0 * unit(c.g), s.b = 255.0 * unit(c.b);
    alpha = unit(c.a);
  }
  // A PBR material's roughness first: assimp's glTF reader also writes a
  // shininess of its own making, (1 - r)^2 x 1000, which is no exponent.
  float shininess = 0, roughness = -1;
  if (m.Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness) == AI_SUCCESS && std::isfinite(roughness)) {
    // Blinn-Phong's exponent of the same lobe width: n = 2 / r^4 - 2.
    const double r = std::clamp(double(roughness), 0.05, 1.0);
    s.n = std::clamp(2.0 / std::pow(r, 4) - 2.0, kMinSpecularExponent, kMaxSpecularExponent);
    notes["PBR metal/roughness approximated: roughness sets the specular exponent n (2/r^4 - 2), metalness is not "
          "modelled"]++;
  } else if (m.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && std::isfinite(shininess) && shininess > 0) {
    s.n = std::clamp(double(shininess), kMinSpecularExponent, kMaxSpecularExponent);
  }
  float opacity = 1;
  if (m.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && std::isfinite(opacity)) alpha = std::min(alpha, double(opacity));
  // glTF: alpha is a transparency only in BLEND mode (OPAQUE, the default,
  // and MASK ignore it; a mask's cut-outs cannot be drawn per pixel here).
  aiString alpha_mode;
  if (m.Get(AI_MATKEY_GLTF_ALPHAMODE, alpha_mode) == AI_SUCCESS && std::string(alpha_mode.C_Str()) != "BLEND") {
    if (std::string(alpha_mode.C_Str()) == "MASK") notes["glTF alpha masks are drawn opaque (no per-pixel cut-out)"]++;
    alpha = 1;
  }
  if (alpha <= 0) {
    notes["a material with opacity 0 (invisible) is drawn opaque: exporters write 0 for 'not set'"]++;
  } else if (alpha < 1) {
    s.t_min = s.t_max = 1.0 - alpha;  // Tf, the same at every angle
  }
  return s;
}

std::string diffuse_texture(const aiMaterial& m) {
  aiString path;
  for (aiTextureType t : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE})
    if (m.GetTextureCount(t) > 0 && m.GetTexture(t, 0, &path) == AI_SUCCESS && path.length > 0) return path.C_Str();
  return "";
}

// A material the importer made up where the file has none: assimp's
// DefaultMaterial, or the unnamed grey its OFF, PLY and STL readers add
// (those formats hold no materials; a PLY `material` element is not read).
bool importer_filler(const std::string& name, const std::string& model_path) {
  if (name == AI_DEFAULT_MATERIAL_NAME) return true;
  std::string ext = fs::path(model_path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return name.empty() && (ext == ".off" || ext == ".ply" || ext == ".stl");
}

}  // namespace

ModelLook::ModelLook(const aiScene& scene, const std::string& model_path, const MadeUpMaterials& made_up)
    : scene_(scene), folder_(fs::path(model_path).parent_path().string()) {
  for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
    const aiMaterial& m = *scene.mMaterials[i];
    aiString name;
    m.Get(AI_MATKEY_NAME, name);
    const bool filler = made_up.all || made_up.names.count(name.C_Str()) || importer_filler(name.C_Str(), model_path);
    surfaces_.push_back(filler ? std::nullopt : std::optional<Surface>(surface_of(m, notes_)));
    texture_of_.push_back(filler ? "" : diffuse_texture(m));
  }
}

const ModelLook::Image* ModelLook::image(const std::string& name) {
  auto found = images_.find(name);
  if (found != images_.end()) return found->second ? &*found->second : nullptr;
  std::optional<Image>& slot = images_[name];
  int w = 0, h = 0, channels = 0;
  // Too many texels would exhaust the import's memory and lose the model.
  auto fits = [&](uint64_t width, uint64_t height) {
    if (width * height <= kMaxTexels) return true;
    too_large_.push_back(name);
    return false;
  };
  std::unique_ptr<unsigned char, void (*)(void*)> pixels(nullptr, stbi_image_free);
  if (const aiTexture* t = scene_.GetEmbeddedTexture(name.c_str())) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(t->pcData);
    if (t->mHeight == 0) {  // a compressed file (PNG, JPEG, ...) of mWidth bytes
      if (t->mWidth <= INT32_MAX && stbi_info_from_memory(bytes, int(t->mWidth), &w, &h, &channels) && fits(w, h))
        pixels.reset(stbi_load_from_memory(bytes, int(t->mWidth), &w, &h, &channels, 3));
    } else if (fits(t->mWidth, t->mHeight)) {  // raw BGRA texels
      Image img{int(t->mWidth), int(t->mHeight), {}};
      img.rgb.reserve(size_t(img.width) * img.height * 3);
      for (size_t i = 0; i < size_t(img.width) * img.height; ++i)
        img.rgb.insert(img.rgb.end(), {t->pcData[i].r, t->pcData[i].g, t->pcData[i].b});
      slot = std::move(img);
      return &*slot;
    } else {
      return nullptr;
    }
  } else {
    std::string relative = name;
    std::replace(relative.begin(), relative.end(), '\\', '/');  // Windows exporters
    fs::path file = fs::path(folder_) / relative;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) file = fs::path(folder_) / fs::path(relative).filename();
    if (fs::is_regular_file(file, ec) && stbi_info(file.c_str(), &w, &h, &channels) && fits(w, h))
      pixels.reset(stbi_load(file.c_str(), &w, &h, &channels, 3));
  }
  if (!pixels || w <= 0 || h <= 0) {
    if (too_large_.empty() || too_large_.back() != name) unreadable_.push_back(name);
    return nullptr;
  }
  Image img{w, h, {}};
  img.rgb.assign(pixels.get(), pixels.get() + size_t(w) * h * 3);
  slot = std::move(img);
  return &*slot;
}

std::optional<CornerColour> ModelLook::texture_mean(unsigned m, const std::vector<aiVector3D>& uv) {
  if (!has_texture(m) || uv.size() < 3) return std::nullopt;
  const Image* img = image(texture_of_[m]);
  if (!img) return std::nullopt;
  note("textures are drawn as their mean colour over each face (a Gouraud machine has no texture memory)");
  // Nearest texel, repeated outside 0..1; v = 0 is the image's bottom row.
  auto texel = [&](double u, double v) {
    u -= std::floor(u), v -= std::floor(v);
    const int x = std::min(img->width - 1, int(u * img->width));
    const int y = std::min(img->height - 1, int((1.0 - v) * img->height));
    return &img->rgb[(size_t(y) * img->width + x) * 3];
  };
  // Each fan triangle (0, k, k+1) split in 9 equal parts, sampled at their
  // centroids and weighted by the triangle's area in the texture.
  constexpr int kSplit = 3;
  double sum[3] = {0, 0, 0}, weight = 0;
  for (size_t k = 1; k + 1 < uv.size(); ++k) {
    const aiVector3D a = uv[0], b = uv[k], c = uv[k + 1];
    double area = std::fabs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    if (!std::isfinite(area)) continue;
    if (area == 0) area = 1e-12;  // a sliver still has a colour
    for (int i = 0; i < kSplit; ++i)
      for (int j = 0; i + j < kSplit; ++j)
        for (int up = 0; up < (i + j < kSplit - 1 ? 2 : 1); ++up) {
          const double s = (i + (up ? 2.0 : 1.0) / 3) / kSplit, t = (j + (up ? 2.0 : 1.0) / 3) / kSplit;
          const uint8_t* p = texel(a.x + s * (b.x - a.x) + t * (c.x - a.x), a.y + s * (b.y - a.y) + t * (c.y - a.y));
          for (int ch = 0; ch < 3; ++ch) sum[ch] += area * (p[ch] / 255.0);
          weight += area;
        }
  }
  if (weight == 0) return std::nullopt;
  return CornerColour{float(sum[0] / weight), float(sum[1] / weight), float(sum[2] / weight)};
}

namespace {
std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}
}  // namespace

std::vector<std::string> ModelLook::warnings() const {
  std::vector<std::string> out;
  for (const auto& [what, count] : notes_) out.push_back(what);
  if (!unreadable_.empty())
    out.push_back("textures that could not be read are left out (their materials' colours are drawn): " +
                  listed(unreadable_));
  if (!too_large_.empty())
    out.push_back("textures of more than " + std::to_string(kMaxTexels >> 20) +
                  " Mi texels are left out (their materials' colours are drawn): " + listed(too_large_));
  return out;
}

}  // namespace girtd
