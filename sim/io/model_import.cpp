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
#include <sstream>
#include <tuple>

#include "common/input_error.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

std::string lower_extension(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) { throw InputError(path, line, what); }

// Counts in a header are checked against the file size before assimp sees
// them: every element needs at least one byte, so a larger count is a lie
// (assimp would try to allocate for it).
void check_claimed_count(const std::string& path, int line, uint64_t claimed, uint64_t file_size, const char* what) {
  if (claimed > file_size)
    fail(path, line,
         std::string("header claims ") + std::to_string(claimed) + " " + what + ", more than the file's " +
             std::to_string(file_size) + " bytes could hold");
}

void precheck_off(const std::string& path, uint64_t size) {
  std::ifstream in(path);
  std::string line;
  int line_no = 0;
  std::vector<std::string> tokens;
  int counts_line = 0;
  while (tokens.size() < 4 && std::getline(in, line)) {
    ++line_no;
    line = line.substr(0, line.find('#'));
    std::istringstream s(line);
    for (std::string t; s >> t;) {
      if (tokens.empty() && t.size() >= 3 && t.compare(t.size() - 3, 3, "OFF") == 0) {
        tokens.push_back(t);
        continue;
      }
      if (tokens.empty()) tokens.push_back("");  // headerless OFF
      if (tokens.size() == 1) counts_line = line_no;
      tokens.push_back(t);
    }
  }
  if (tokens.size() < 3) fail(path, line_no, "OFF file without vertex and face counts");
  for (size_t i = 1; i < 3; ++i) {
    const std::string& t = tokens[i];
    if (t.empty() || !std::all_of(t.begin(), t.end(), [](unsigned char c) { return std::isdigit(c); }) || t.size() > 18)
      fail(path, counts_line, "OFF count '" + t + "' is not a non-negative integer");
    check_claimed_count(path, counts_line, std::stoull(t), size, i == 1 ? "vertices" : "faces");
  }
}

void precheck_ply(const std::string& path, uint64_t size) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  int line_no = 0;
  while (std::getline(in, line) && line_no < 1000) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line == "end_header") return;
    std::istringstream s(line);
    std::string kw, name, count;
    s >> kw >> name >> count;
    if (kw != "element") continue;
    if (count.empty() || count.size() > 18 ||
        !std::all_of(count.begin(), count.end(), [](unsigned char c) { return std::isdigit(c); }))
      fail(path, line_no, "PLY element '" + name + "' count '" + count + "' is not a non-negative integer");
    check_claimed_count(path, line_no, std::stoull(count), size, (name + " elements").c_str());
  }
}

void precheck_stl(const std::string& path, uint64_t size) {
  std::ifstream in(path, std::ios::binary);
  char head[84] = {};
  in.read(head, sizeof head);
  if (std::string(head, 5) == "solid") return;  // ASCII STL: no counts
  if (in.gcount() < 84) fail(path, 0, "binary STL shorter than its 84-byte header");
  uint32_t n = 0;
  for (int i = 3; i >= 0; --i) n = (n << 8) | static_cast<unsigned char>(head[80 + i]);
  if (84 + 50 * uint64_t{n} != size)
    fail(path, 0,
         "binary STL claims " + std::to_string(n) + " triangles (" + std::to_string(84 + 50 * uint64_t{n}) +
             " bytes) but the file has " + std::to_string(size) + " bytes");
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
        const int idx = index_of[face.mIndices[k]];
        if (poly.empty() || poly.back() != idx) poly.push_back(idx);  // repeated corner: drop
      }
      if (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
      if (poly.size() >= 3) mesh_.polygons.push_back(std::move(poly));
    }
  }

  std::string path_;
  Mesh mesh_;
  std::map<std::tuple<double, double, double>, int> index_;
};

}  // namespace

bool is_model_file(const std::string& path) {
  const std::string e = lower_extension(path);
  if (e.empty()) return false;
  return aiIsExtensionSupported(e.c_str()) == AI_TRUE;
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
  if (ext == ".off") precheck_off(path, size);
  if (ext == ".ply") precheck_ply(path, size);
  if (ext == ".stl") precheck_stl(path, size);

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
