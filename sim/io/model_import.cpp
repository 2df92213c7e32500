#include "io/model_import.hpp"

#include <assimp/DefaultIOSystem.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
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
#include <tuple>

#include "common/input_error.hpp"
#include "frontend/polygon_shape.hpp"
#include "io/assimp_messages.hpp"
#include "io/import_child.hpp"
#include "io/model_precheck.hpp"
#include "io/model_tokens.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

std::string lower_extension(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}


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

// Opens the model file and nothing else: materials in model files are not
// used, and what a material library can do to assimp 5.2.5 is worse than
// missing it: a bad number or a 1-7 byte .mtl fails a model that can be
// drawn, a name it can open but not read throws "File read error" (and
// leaks), a pipe never ends. The
// OBJ pre-check warns of missing libraries and names itself.
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

class MeshBuilder {
 public:
  explicit MeshBuilder(const std::string& path) : path_(path) {}

  void add(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent) {
    const aiMatrix4x4 m = parent * node.mTransformation;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
      if (node.mMeshes[i] >= scene.mNumMeshes) fail(path_, 0, "node refers to a mesh that does not exist");
      add_mesh(*scene.mMeshes[node.mMeshes[i]], m);
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) add(scene, *node.mChildren[i], m);
  }

  // `file_polygons`: what the pre-check counted (its formats only).
  Mesh take(std::optional<uint64_t> file_polygons) {
    // Some damage reaches no log (sim/io/README.md): the count is the check.
    if (file_polygons && faces_read_ != *file_polygons)
      fail(path_, 0,
           "assimp 5.2.5 returned " + std::to_string(faces_read_) + " polygons where the pre-check counted " +
               std::to_string(*file_polygons) + ": refused rather than drawn wrong");
    if (mesh_.polygons.empty()) fail(path_, 0, "the model has no polygons (points and lines are not drawn)");
    return std::move(mesh_);
  }

 private:
  void add_mesh(const aiMesh& am, const aiMatrix4x4& m) {
    std::vector<int> index_of(am.mNumVertices);
    for (unsigned v = 0; v < am.mNumVertices; ++v) {
      const aiVector3D p = m * am.mVertices[v];
      const Vec3 w{p.x, p.y, p.z};
      if (!finite(w)) fail(path_, 0, "vertex " + std::to_string(v) + " has a coordinate that is NaN or infinite");
      auto [it, fresh] = index_.emplace(std::make_tuple(w.x, w.y, w.z), static_cast<int>(mesh_.positions.size()));
      if (fresh) mesh_.positions.push_back(w);
      index_of[v] = it->second;
    }
    for (unsigned f = 0; f < am.mNumFaces; ++f) {
      const aiFace& face = am.mFaces[f];
      if (face.mNumIndices < 3) continue;  // points and lines
      ++faces_read_;
      if (face.mNumIndices > kMaxPolygonVertices)
        fail(path_, 0, "face " + std::to_string(f) + " has " + std::to_string(face.mNumIndices) + " vertices (limit " +
                           std::to_string(kMaxPolygonVertices) + ")");
      if (mesh_.polygons.size() >= kMaxModelPolygons)
        fail(path_, 0, "more than " + std::to_string(kMaxModelPolygons) + " polygons");
      std::vector<int> poly;
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        if (face.mIndices[k] >= am.mNumVertices)
          fail(path_, 0, "face " + std::to_string(f) + " refers to vertex " + std::to_string(face.mIndices[k]) +
                             " of " + std::to_string(am.mNumVertices));
        poly.push_back(index_of[face.mIndices[k]]);
      }
      drop_repeated_corners(poly, [](int a, int b) { return a == b; });
      if (poly.size() >= 3) mesh_.polygons.push_back(std::move(poly));
    }
  }

  std::string path_;
  Mesh mesh_;
  uint64_t faces_read_ = 0;
  std::map<std::tuple<double, double, double>, int> index_;
};

// The file itself, then the pre-check where its format has one: the polygons
// it counted, for checking what assimp returns against.
std::optional<uint64_t> check_file(const std::string& path, std::vector<std::string>& warnings) {
  std::error_code ec;
  if (!fs::exists(path, ec)) fail(path, 0, "no such file");
  if (!fs::is_regular_file(path, ec)) fail(path, 0, "not a regular file");
  const uint64_t size = fs::file_size(path, ec);
  if (ec) fail(path, 0, "cannot read file size");
  if (size == 0) fail(path, 0, "empty file");
  if (!std::ifstream(path)) fail(path, 0, "cannot open file");
  const std::string ext = lower_extension(path);
  if (!is_checked_model_format(ext)) return std::nullopt;
  return precheck_model(path, ext, size, warnings);
}

// assimp, and the checks on what it returns.
Mesh assimp_import(const std::string& path, std::optional<uint64_t> file_polygons, std::vector<std::string>& warnings) {
  // No aiProcess_Triangulate: polygons must reach the GIRTD triangulator.
  const unsigned flags = aiProcess_JoinIdenticalVertices | aiProcess_ValidateDataStructure;
  MessageLog log;
  Assimp::Importer importer;
  // The pre-checked formats open their own file only (an OBJ's material
  // library is trouble, above); the others open what they name (a glTF's
  // buffers), inside the child's limits.
  if (file_polygons) importer.SetIOHandler(new OnlyTheModelFile(path));  // the importer owns it
  const aiScene* scene = importer.ReadFile(path, flags);
  if (!scene || !scene->mRootNode) fail_assimp(path, importer);
  if (!log.first_error().empty()) fail(path, 0, "cannot read the model: " + log.first_error());
  MeshBuilder b(path);
  b.add(*scene, *scene->mRootNode, aiMatrix4x4());
  Mesh mesh = b.take(file_polygons);
  for (const std::string& w : log.warnings()) warnings.push_back(path + ": " + w);
  return mesh;
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

Mesh import_model_in_process(const std::string& path, std::vector<std::string>& warnings) {
  std::vector<std::string> found;  // the pre-check's first, then assimp's
  const std::optional<uint64_t> file_polygons = check_file(path, found);
  Mesh mesh = assimp_import(path, file_polygons, found);
  warnings.insert(warnings.end(), found.begin(), found.end());
  return mesh;
}

Mesh import_model(const std::string& path, std::vector<std::string>& warnings) {
  std::vector<std::string> found;
  const std::optional<uint64_t> file_polygons = check_file(path, found);
  Mesh mesh = import_in_child(
      path, kImportLimits, [&](std::vector<std::string>& child_warnings) {
        return assimp_import(path, file_polygons, child_warnings);
      },
      found);
  warnings.insert(warnings.end(), found.begin(), found.end());
  return mesh;
}

}  // namespace girtd
