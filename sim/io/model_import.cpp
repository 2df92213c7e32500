#include "io/model_import.hpp"

#include <assimp/DefaultIOSystem.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <tuple>

#include "common/input_error.hpp"
#include "frontend/polygon_shape.hpp"
#include "frontend/position_weld.hpp"
#include "io/assimp_messages.hpp"
#include "io/import_child.hpp"
#include "io/model_precheck.hpp"
#include "io/model_materials.hpp"
#include "io/model_tokens.hpp"
#include "io/scene_defaults.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

std::string lower_extension(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}


float unit(float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f; }

// assimp's message, with "line N" turned into the error's line when present.
[[noreturn]] void fail_assimp(const std::string& path, const Assimp::Importer& importer) {
  std::string msg = importer.GetErrorString();
  int line = 0;
  std::smatch m;
  int64_t at = 0;
  if (std::regex_search(msg, m, std::regex("[Ll]ine\\s*:?\\s*(\\d{1,9})")) && read_integer(m.str(1), at) == NumberRead::kOk)
    line = int(at);
  while (!msg.empty() && std::isspace(static_cast<unsigned char>(msg.back()))) msg.pop_back();
  // assimp catches an allocation that failed under the child's limit itself.
  if (msg.find("bad_alloc") != std::string::npos) fail(path, 0, out_of_memory_message(kImportLimits));
  fail(path, line, "cannot read the model: " + (msg.empty() ? std::string("unknown format or empty file") : msg));
}

// Keeps assimp quiet (nothing on stdout) and keeps what it logs at Warn and
// Err severity, sorted (io/assimp_messages): some readers log a broken index,
// clamp it and carry on (OFF); others log a missing material and carry on
// with a default one (OBJ).
class MessageLog : public Assimp::LogStream {
 public:
  MessageLog() : warn_(this, false), err_(this, true) {
    Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);  // no default streams
    Assimp::DefaultLogger::get()->attachStream(&warn_, Assimp::Logger::Warn);
    Assimp::DefaultLogger::get()->attachStream(&err_, Assimp::Logger::Err);
  }
  ~MessageLog() override {
    Assimp::DefaultLogger::get()->detachStream(&warn_, Assimp::Logger::Warn);
    Assimp::DefaultLogger::get()->detachStream(&err_, Assimp::Logger::Err);
    Assimp::DefaultLogger::kill();
  }
  void write(const char*) override {}
  const std::string& first_error() const { return first_error_; }
  // Each warning once, in the order first logged, with how often it came.
  std::vector<std::string> warnings() const {
    std::vector<std::string> out;
    for (const auto& [text, count] : warnings_)
      out.push_back(count == 1 ? text : text + " (" + std::to_string(count) + " times)");
    return out;
  }

 private:
  struct Severity : Assimp::LogStream {
    Severity(MessageLog* log, bool error) : log_(log), error_(error) {}
    void write(const char* message) override { log_->add(strip_assimp_prefix(message), error_); }
    MessageLog* log_;
    bool error_;
  };
  void add(const std::string& text, bool logged_as_error) {
    const AssimpMessage kind = classify_assimp_message(text, logged_as_error);
    if (kind == AssimpMessage::kIgnored) return;
    if (kind == AssimpMessage::kError) {
      if (first_error_.empty()) first_error_ = text;
      return;
    }
    for (auto& [seen, count] : warnings_)
      if (seen == text) {
        ++count;
        return;
      }
    warnings_.emplace_back(text, 1);
  }
  Severity warn_, err_;
  std::string first_error_;
  std::vector<std::pair<std::string, int>> warnings_;
};

// The import's progress line: assimp's reading is the first kReadShare of
// it, MeshBuilder's the rest. Readers that report file reading (OBJ, PLY,
// ...) report it as the first half of Update's range, post-processing the
// second: here reading is the whole.
constexpr double kReadShare = 0.8;
class ReadProgress : public Assimp::ProgressHandler {
 public:
  bool Update(float share) override {
    if (share >= 0) report_import_progress(kReadShare * share);
    return true;
  }
  void UpdateFileRead(int step, int steps) override {
    if (steps > 0) report_import_progress(kReadShare * double(step) / double(steps));
  }
};

// Opens regular files only: a model naming a FIFO or a device (as a glTF's
// buffer or an OBJ's material library) would block or read forever.
class RegularFilesOnly : public Assimp::DefaultIOSystem {
 public:
  bool Exists(const char* file) const override { return regular(file) && DefaultIOSystem::Exists(file); }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    return regular(file) ? DefaultIOSystem::Open(file, mode) : nullptr;
  }

 private:
  static bool regular(const char* file) {
    std::error_code ec;
    return fs::is_regular_file(file, ec);
  }
};

// Opens the model file and nothing else: the second try of a pre-checked
// format whose material library failed it. What an .mtl can do to assimp
// 5.2.5: a bad number or a 1-7 byte file fails a model that can be drawn, a
// name it can open but not read throws "File read error" (and leaks).
class OnlyTheModelFile : public Assimp::DefaultIOSystem {
 public:
  explicit OnlyTheModelFile(const std::string& path) : model_(canonical(path)) {}
  bool Exists(const char* file) const override { return is_model(file) && DefaultIOSystem::Exists(file); }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    return is_model(file) ? DefaultIOSystem::Open(file, mode) : nullptr;
  }

 private:
  static std::string canonical(const std::string& path) {
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(path, ec);
    return ec ? std::string() : p.string();
  }
  bool is_model(const char* file) const { return !model_.empty() && canonical(file) == model_; }
  std::string model_;
};

// The polygons of every node's meshes, placed by the node's transform, with
// their materials and corner colours; and the transform of every node, by
// name, for the cameras and lights that hang on nodes.
class MeshBuilder {
 public:
  MeshBuilder(const std::string& path, const aiScene& scene, const MadeUpMaterials& made_up)
      : path_(path), scene_(scene), look_(scene, path, made_up) {
    for (unsigned i = 0; i < scene.mNumMeshes; ++i) faces_in_file_ += scene.mMeshes[i]->mNumFaces;
  }

  void add(const aiNode& node, const aiMatrix4x4& parent) {
    const aiMatrix4x4 m = parent * node.mTransformation;
    node_transform_.emplace(node.mName.C_Str(), m);  // the first node of a name
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
      if (node.mMeshes[i] >= scene_.mNumMeshes) fail(path_, 0, "node refers to a mesh that does not exist");
      add_mesh(*scene_.mMeshes[node.mMeshes[i]], m);
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) add(*node.mChildren[i], m);
  }

  // `file_polygons`: what the pre-check counted (its formats only).
  ImportedModel take(std::optional<uint64_t> file_polygons, std::vector<std::string>& warnings) {
    // Some damage reaches no log (sim/io/README.md): the count is the check.
    if (file_polygons && faces_read_ != *file_polygons)
      fail(path_, 0,
           "assimp 5.2.5 returned " + std::to_string(faces_read_) + " polygons where the pre-check counted " +
               std::to_string(*file_polygons) + ": refused rather than drawn wrong");
    if (model_.mesh.polygon_count() == 0) fail(path_, 0, "the model has no polygons (points and lines are not drawn)");
    model_.materials = look_.surfaces();
    if (!any_corner_colour_) model_.mesh.corner_colour.clear();
    add_cameras();
    add_lights();
    for (const std::string& w : look_.warnings()) warnings.push_back(path_ + ": " + w);
    return std::move(model_);
  }

 private:
  void add_mesh(const aiMesh& am, const aiMatrix4x4& m) {
    Mesh& mesh = model_.mesh;
    // Welded when a face first uses it: a vertex no face uses is not a
    // position of the model (it would move the box lights are aimed by) and
    // is not checked.
    std::vector<int> index_of(am.mNumVertices, -1);
    auto welded = [&](unsigned v) {
      if (index_of[v] >= 0) return index_of[v];
      const aiVector3D p = m * am.mVertices[v];
      const Vec3 w{p.x, p.y, p.z};
      if (!finite(w)) fail(path_, 0, "vertex " + std::to_string(v) + " has a coordinate that is NaN or infinite");
      return index_of[v] = weld_.index_of(w, mesh.positions);
    };
    const unsigned material = am.mMaterialIndex < scene_.mNumMaterials ? am.mMaterialIndex : 0;
    const int key = material_key(material);  // the same for every face of the mesh
    const Surface surface = material < look_.surfaces().size() && look_.surfaces()[material]
                                ? *look_.surfaces()[material]
                                : SceneDefaults::material();
    const bool vertex_colours = am.HasVertexColors(0);
    const bool mirrors = m.Determinant() < 0;
    const bool textured = am.HasTextureCoords(0) && look_.has_texture(material);
    struct Corner {
      int index;
      CornerColour colour;
    };
    std::vector<Corner> corners;
    std::vector<aiVector3D> uv;
    for (unsigned f = 0; f < am.mNumFaces; ++f) {
      if ((++faces_seen_ & 0xffff) == 0 && faces_in_file_ > 0)
        report_import_progress(kReadShare + (1 - kReadShare) * double(faces_seen_) / double(faces_in_file_));
      const aiFace& face = am.mFaces[f];
      if (face.mNumIndices < 3) continue;  // points and lines
      ++faces_read_;
      if (face.mNumIndices > kMaxPolygonVertices)
        fail(path_, 0, "face " + std::to_string(f) + " has " + std::to_string(face.mNumIndices) + " vertices (limit " +
                           std::to_string(kMaxPolygonVertices) + ")");
      if (mesh.polygon_count() >= kMaxModelPolygons)
        fail(path_, 0, "more than " + std::to_string(kMaxModelPolygons) + " polygons");
      corners.clear();
      uv.clear();
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        const unsigned v = face.mIndices[k];
        if (v >= am.mNumVertices)
          fail(path_, 0, "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " of " +
                             std::to_string(am.mNumVertices));
        // Vertex colours replace the material's colour (sim/io/README.md "Materials").
        CornerColour c{float(surface.r), float(surface.g), float(surface.b)};
        if (vertex_colours) {
          const aiColor4D vc = am.mColors[0][v];
          c = {255.0f * unit(vc.r), 255.0f * unit(vc.g), 255.0f * unit(vc.b)};
        }
        corners.push_back({welded(v), c});
        if (textured) uv.push_back(am.mTextureCoords[0][v]);
      }
      if (textured)
        if (const std::optional<CornerColour> t = look_.texture_mean(material, uv))
          for (Corner& c : corners) c.colour = {c.colour.r * t->r, c.colour.g * t->g, c.colour.b * t->b};
      // A mirroring transform turns the winding: counter-clockwise again.
      if (mirrors) std::reverse(corners.begin(), corners.end());
      drop_repeated_corners(corners, [](const Corner& a, const Corner& b) { return a.index == b.index; });
      if (corners.size() < 3) continue;
      for (const Corner& c : corners) {
        mesh.corners.push_back(c.index);
        mesh.corner_colour.push_back(c.colour);
      }
      mesh.first.push_back(mesh.corners.size());
      mesh.material.push_back(key);
      any_corner_colour_ = any_corner_colour_ || vertex_colours || textured;
    }
  }

  // Polygons of different materials never share a surface; those the
  // importer made up are all the default material, hence one key.
  int material_key(unsigned material) const {
    const auto& s = look_.surfaces();
    if (material < s.size() && s[material]) return int(material);
    for (size_t i = 0; i < s.size(); ++i)
      if (!s[i]) return int(i);
    return int(material);
  }

  // The transform of the node named `name` (a camera's or a light's), or none.
  aiMatrix4x4 placement(const aiString& name) const {
    auto it = node_transform_.find(name.C_Str());
    return it == node_transform_.end() ? aiMatrix4x4() : it->second;
  }
  static Vec3 vec(const aiVector3D& v) { return {v.x, v.y, v.z}; }
  static Vec3 direction(const aiMatrix4x4& m, const aiVector3D& d) {
    const Vec3 w = vec(aiMatrix3x3(m) * d);
    return length(w) > 0 && finite(w) ? normalized(w) : Vec3{};
  }

  // glTF puts cameras and lights at their node's origin; assimp 5.2.5 also
  // copies the node's translation into aiCamera::mPosition, which the node's
  // transform would then apply twice.
  bool gltf() const {
    const std::string ext = lower_extension(path_);
    return ext == ".gltf" || ext == ".glb";
  }

  void add_cameras() {
    for (unsigned i = 0; i < scene_.mNumCameras; ++i) {
      const aiCamera& c = *scene_.mCameras[i];
      const aiMatrix4x4 m = placement(c.mName);
      ModelCamera cam;
      cam.name = c.mName.C_Str();
      cam.eye = vec(m * (gltf() ? aiVector3D() : c.mPosition));
      cam.forward = direction(m, c.mLookAt);
      cam.up = direction(m, c.mUp);
      // assimp 5.2.5's mHorizontalFOV is the whole horizontal angle (Collada,
      // 3DS and FBX measured), for glTF the vertical angle times the aspect
      // ratio (sim/io/README.md "Materials, cameras and lights"). GIRTD's
      // screen is square: that angle spans it.
      double fov = c.mHorizontalFOV;
      if (gltf() && c.mAspect > 0) fov /= c.mAspect;
      cam.fov_deg = fov * 180.0 / M_PI;
      cam.near = std::isfinite(c.mClipPlaneNear) && c.mClipPlaneNear > 0 ? c.mClipPlaneNear : 0;
      cam.orthographic = c.mOrthographicWidth > 0;
      if (!finite(cam.eye) || !std::isfinite(cam.fov_deg)) continue;
      model_.cameras.push_back(cam);
    }
  }

  void add_lights() {
    for (unsigned i = 0; i < scene_.mNumLights; ++i) {
      const aiLight& l = *scene_.mLights[i];
      const aiMatrix4x4 m = placement(l.mName);
      ModelLight light;
      light.name = l.mName.C_Str();
      switch (l.mType) {
        case aiLightSource_DIRECTIONAL: light.kind = ModelLightKind::kDirectional; break;
        case aiLightSource_POINT: light.kind = ModelLightKind::kPoint; break;
        case aiLightSource_SPOT: light.kind = ModelLightKind::kSpot; break;
        case aiLightSource_AREA: light.kind = ModelLightKind::kArea; break;
        case aiLightSource_AMBIENT: light.kind = ModelLightKind::kAmbient; break;
        default: light.kind = ModelLightKind::kOther; break;
      }
      light.position = vec(m * (gltf() ? aiVector3D() : l.mPosition));
      light.direction = direction(m, l.mDirection);
      const aiColor3D c = l.mColorDiffuse;
      const double hi = std::max({double(c.r), double(c.g), double(c.b)});
      light.strength = std::isfinite(hi) && hi > 0 ? hi : 0;
      const double lo = std::min({double(c.r), double(c.g), double(c.b)});
      light.coloured = light.strength > 0 && lo < 0.99 * hi;
      if (!finite(light.position)) continue;
      model_.lights.push_back(light);
    }
  }

  std::string path_;
  const aiScene& scene_;
  ModelLook look_;
  ImportedModel model_;
  uint64_t faces_read_ = 0;
  uint64_t faces_seen_ = 0, faces_in_file_ = 0;  // for the progress line (a mesh placed twice counts twice)
  bool any_corner_colour_ = false;
  PositionWeld weld_;  // across the file's meshes
  std::map<std::string, aiMatrix4x4> node_transform_;
};

// The file itself, then the pre-check where its format has one: the polygons
// it counted, for checking what assimp returns against.
std::optional<PrecheckResult> check_file(const std::string& path, std::vector<std::string>& warnings) {
  std::error_code ec;
  if (!fs::exists(path, ec)) fail(path, 0, "no such file");
  if (!fs::is_regular_file(path, ec)) fail(path, 0, "not a regular file");
  const uint64_t size = fs::file_size(path, ec);
  if (ec) fail(path, 0, "cannot read file size");
  if (size == 0) fail(path, 0, "empty file");
  if (!std::ifstream(path)) fail(path, 0, "cannot open file");
  const std::string ext = lower_extension(path);
  if (ext == ".gltf" || ext == ".glb") {
    precheck_gltf(path, read_model_bytes(path, size));
    return std::nullopt;
  }
  if (!is_checked_model_format(ext)) return std::nullopt;
  return precheck_model(path, ext, size, warnings);
}

// What assimp read, built and checked; its log's warnings after the model's.
// `library_lost`: imported without its material library, so every material
// is one assimp made up for a usemtl.
ImportedModel build(const std::string& path, const aiScene& scene, const std::optional<PrecheckResult>& checked,
                    bool library_lost, const MessageLog& log, std::vector<std::string>& warnings) {
  MadeUpMaterials made_up;
  made_up.all = library_lost;
  if (checked) made_up.names = checked->undefined_materials;
  MeshBuilder b(path, scene, made_up);
  b.add(*scene.mRootNode, aiMatrix4x4());
  std::vector<std::string> look;
  ImportedModel model = b.take(checked ? std::optional<uint64_t>(checked->polygons) : std::nullopt, look);
  for (const std::string& w : log.warnings()) warnings.push_back(path + ": " + w);
  warnings.insert(warnings.end(), look.begin(), look.end());
  return model;
}

// assimp, and the checks on what it returns.
ImportedModel assimp_import(const std::string& path, const std::optional<PrecheckResult>& checked,
                            std::vector<std::string>& warnings) {
  // No aiProcess_Triangulate: polygons must reach the GIRTD triangulator. No
  // aiProcess_JoinIdenticalVertices: MeshBuilder welds by position itself
  // (that step tripled a 10^6-triangle OBJ's import time). The formats the
  // pre-check read have a scene graph assimp makes itself, and MeshBuilder
  // checks every index: assimp's validation (+40 % there) runs for the others.
  const unsigned flags = checked ? 0u : unsigned(aiProcess_ValidateDataStructure);
  std::string with_its_files;  // why the import with the files the model names failed
  {
    MessageLog log;
    Assimp::Importer importer;
    importer.SetIOHandler(new RegularFilesOnly());  // the importer owns it
    importer.SetProgressHandler(new ReadProgress());  // likewise
    const aiScene* scene = importer.ReadFile(path, flags);
    if (scene && scene->mRootNode && log.first_error().empty()) return build(path, *scene, checked, false, log, warnings);
    if (!checked) {
      if (!scene || !scene->mRootNode) fail_assimp(path, importer);
      fail(path, 0, "cannot read the model: " + log.first_error());
    }
    with_its_files = !scene || !scene->mRootNode ? importer.GetErrorString() : log.first_error();
  }
  // A pre-checked format (OBJ) may have failed on its material library:
  // once more with the model file alone, whose errors are the model's.
  MessageLog log;
  Assimp::Importer importer;
  importer.SetIOHandler(new OnlyTheModelFile(path));
  importer.SetProgressHandler(new ReadProgress());
  const aiScene* scene = importer.ReadFile(path, flags);
  if (!scene || !scene->mRootNode) fail_assimp(path, importer);
  if (!log.first_error().empty()) fail(path, 0, "cannot read the model: " + log.first_error());
  while (!with_its_files.empty() && std::isspace(static_cast<unsigned char>(with_its_files.back()))) with_its_files.pop_back();
  warnings.push_back(path + ": the files it names (its material library) could not be read (" + with_its_files +
                     "): drawn with the default material");
  return build(path, *scene, checked, true, log, warnings);
}

}  // namespace

bool is_model_file(const std::string& path) {
  const std::string e = lower_extension(path);
  // assimp's RAW format (a text dump of numbers) would take a headerless
  // trace named .raw without a word: such a file stays a trace (--level);
  // a RAW model can still be named by a scene's "file".
  if (e.empty() || e == ".raw") return false;
  return is_checked_model_format(e) || Assimp::Importer().IsExtensionSupported(e);
}

ImportedModel import_model_in_process(const std::string& path, std::vector<std::string>& warnings) {
  std::vector<std::string> found;  // the pre-check's first, then assimp's
  const std::optional<PrecheckResult> checked = check_file(path, found);
  ImportedModel model = assimp_import(path, checked, found);
  warnings.insert(warnings.end(), found.begin(), found.end());
  return model;
}

ImportedModel import_model(const std::string& path, std::vector<std::string>& warnings) {
  std::vector<std::string> found;
  const std::optional<PrecheckResult> checked = check_file(path, found);
  ImportedModel model = import_in_child(
      path, kImportLimits, [&](std::vector<std::string>& child_warnings) {
        return assimp_import(path, checked, child_warnings);
      },
      found);
  warnings.insert(warnings.end(), found.begin(), found.end());
  return model;
}

}  // namespace girtd
