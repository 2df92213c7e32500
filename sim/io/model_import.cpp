#include "io/model_import.hpp"

#include <assimp/DefaultLogger.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <tuple>

#include "common/input_error.hpp"
#include "frontend/polygon_shape.hpp"
#include "io/model_precheck.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

std::string lower_extension(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) { throw InputError(path, line, what); }

[[noreturn]] void fail_format(const std::string& path, const std::string& ext) {
  fail(path, 0,
       "model format '" + (ext.empty() ? std::string("(no extension)") : ext) +
           "' is not read: OBJ, OFF, PLY and STL are (their counts are checked before import)");
}

// assimp's message, with "line N" turned into the error's line when present.
[[noreturn]] void fail_assimp(const std::string& path) {
  std::string msg = aiGetErrorString();
  int line = 0;
  std::smatch m;
  if (std::regex_search(msg, m, std::regex("[Ll]ine\\s*:?\\s*(\\d{1,9})"))) line = std::stoi(m[1]);
  while (!msg.empty() && std::isspace(static_cast<unsigned char>(msg.back()))) msg.pop_back();
  fail(path, line, "cannot read the model: " + (msg.empty() ? std::string("unknown format or empty file") : msg));
}

// Keeps assimp quiet (nothing on stdout) and remembers the first error it
// logs: some readers log a broken index, clamp it and carry on (OFF).
class ErrorCapture : public Assimp::LogStream {
 public:
  ErrorCapture() {
    Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);  // no default streams
    Assimp::DefaultLogger::get()->attachStream(this, Assimp::Logger::Err);
  }
  ~ErrorCapture() override {
    Assimp::DefaultLogger::get()->detachStream(this, Assimp::Logger::Err);
    Assimp::DefaultLogger::kill();
  }
  void write(const char* message) override {
    if (first_.empty()) first_ = message;
  }
  const std::string& first() const { return first_; }

 private:
  std::string first_;
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

  Mesh take() {
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
      if (face.mNumIndices < 3) continue;
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
  std::map<std::tuple<double, double, double>, int> index_;
};

}  // namespace

bool is_model_file(const std::string& path) { return is_checked_model_format(lower_extension(path)); }

void reject_other_model_formats(const std::string& path) {
  const std::string e = lower_extension(path);
  if (!e.empty() && !is_model_file(path) && aiIsExtensionSupported(e.c_str()) == AI_TRUE) fail_format(path, e);
}

Mesh import_model(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) fail(path, 0, "no such file");
  if (!fs::is_regular_file(path, ec)) fail(path, 0, "not a regular file");
  const uint64_t size = fs::file_size(path, ec);
  if (ec) fail(path, 0, "cannot read file size");
  if (size == 0) fail(path, 0, "empty file");
  if (!std::ifstream(path)) fail(path, 0, "cannot open file");
  const std::string ext = lower_extension(path);
  if (!is_checked_model_format(ext)) fail_format(path, ext);
  precheck_model(path, ext, size);

  // No aiProcess_Triangulate: polygons must reach the GIRTD triangulator.
  const unsigned flags = aiProcess_JoinIdenticalVertices | aiProcess_ValidateDataStructure;
  ErrorCapture errors;
  const aiScene* scene = aiImportFile(path.c_str(), flags);
  if (!scene || !scene->mRootNode) fail_assimp(path);
  struct Release {
    const aiScene* s;
    ~Release() { aiReleaseImport(s); }
  } release{scene};
  if (!errors.first().empty()) {
    std::string msg = errors.first();
    while (!msg.empty() && std::isspace(static_cast<unsigned char>(msg.back()))) msg.pop_back();
    const size_t colon = msg.find(": ");  // drop assimp's "Error, T0: " prefix
    fail(path, 0, "cannot read the model: " + (colon == std::string::npos ? msg : msg.substr(colon + 2)));
  }
  MeshBuilder b(path);
  b.add(*scene, *scene->mRootNode, aiMatrix4x4());
  return b.take();
}

}  // namespace girtd
