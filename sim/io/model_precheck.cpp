#include "io/model_precheck.hpp"

#include <cmath>
#include <fstream>
#include <string_view>
#include <vector>

#include "common/input_error.hpp"
#include "io/model_import.hpp"
#include "io/model_tokens.hpp"

namespace girtd {
namespace {

// assimp's OFF reader drops a face of more than this many corners (and logs
// an error): refused here with its line instead.
constexpr int64_t kMaxOffFaceCorners = 9;

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) { throw InputError(path, line, what); }

std::string vertices_text(int64_t n) { return std::to_string(n) + (n == 1 ? " vertex" : " vertices"); }

void check_finite(const std::string& path, int line, int64_t vertex, std::string_view token) {
  double d = 0;
  if (parse_real(token, d) && !std::isfinite(d))
    fail(path, line, "vertex " + std::to_string(vertex) + " has a coordinate that is NaN or infinite");
}

// OBJ: no counts to trust; two passes find the line of a vertex with a NaN
// coordinate and of a face whose index is 0 or out of range (positive
// indices may point forward, as assimp allows; negative ones count back
// from the vertices read so far).
void precheck_obj(const std::string& path) {
  std::vector<std::string_view> tok;
  std::string line;
  int64_t total = 0;
  {
    std::ifstream in(path, std::ios::binary);
    for (int no = 1; std::getline(in, line); ++no) {
      split_tokens(line, tok);
      if (tok.empty() || tok[0] != "v") continue;
      ++total;
      for (size_t k = 1; k < tok.size() && k <= 3; ++k) check_finite(path, no, total, tok[k]);
    }
  }
  std::ifstream in(path, std::ios::binary);
  int64_t seen = 0;
  for (int no = 1; std::getline(in, line); ++no) {
    split_tokens(line, tok);
    if (tok.empty()) continue;
    if (tok[0] == "v") ++seen;
    if (tok[0] != "f") continue;
    for (size_t k = 1; k < tok.size(); ++k) {
      int64_t i = 0;
      if (!parse_leading_integer(tok[k], i)) continue;  // assimp's to judge
      if (i == 0) fail(path, no, "vertex index 0 is out of range (OBJ counts from 1)");
      if (i > total || (i < 0 && seen + i < 0))
        fail(path, no,
             "vertex index " + std::to_string(i) + " is out of range (" +
                 (i > 0 ? "the file has " + vertices_text(total) : vertices_text(seen) + " so far") + ")");
    }
  }
}

// Reads the OFF file line by line; blank and comment lines are skipped.
class OffLines {
 public:
  explicit OffLines(const std::string& path) : in_(path, std::ios::binary) {}
  // The next line with a token; false at the end of the file.
  bool next(std::vector<std::string_view>& tok) {
    while (std::getline(in_, line_)) {
      ++no_;
      split_tokens(line_, tok);
      if (!tok.empty()) return true;
    }
    return false;
  }
  int line() const { return no_; }

 private:
  std::ifstream in_;
  std::string line_;
  int no_ = 0;
};

// OFF: the header's counts against the file size and the limits, then every
// vertex and face line: a face's corner count (what assimp allocates from),
// its indices, NaN coordinates.
void precheck_off(const std::string& path, uint64_t size) {
  OffLines lines(path);
  std::vector<std::string_view> tok;
  if (!lines.next(tok)) fail(path, 0, "OFF file without vertex and face counts");
  // The header's tokens after the keyword ([dimension], vertices, faces,
  // edges), read across lines as assimp does, with their lines.
  const bool keyword = tok[0].size() >= 3 && tok[0].substr(tok[0].size() - 3) == "OFF";
  const bool dimension = keyword && tok[0].find('n') != std::string_view::npos;
  std::vector<std::pair<std::string, int>> header;
  const size_t wanted = 3 + (dimension ? 1 : 0);
  for (size_t at = keyword ? 1 : 0; header.size() < wanted; ++at) {
    if (at == tok.size()) {
      if (!lines.next(tok)) fail(path, lines.line(), "OFF file without vertex and face counts");
      at = 0;
    }
    header.emplace_back(std::string(tok[at]), lines.line());
  }
  const size_t first = dimension ? 1 : 0;
  int64_t count[2] = {0, 0};
  const int counts_line = header[first].second;
  for (size_t i = 0; i < 2; ++i) {
    const std::string& t = header[first + i].first;
    if (!parse_integer(t, count[i]) || count[i] < 0)
      fail(path, counts_line, "OFF count '" + t + "' is not a non-negative integer");
    if (static_cast<uint64_t>(count[i]) > size)
      fail(path, counts_line,
           "header claims " + t + (i == 0 ? " vertices" : " faces") + ", more than the file's " + std::to_string(size) +
               " bytes could hold");
  }
  if (static_cast<uint64_t>(count[1]) > kMaxModelPolygons)
    fail(path, counts_line, "header claims " + std::to_string(count[1]) + " faces (limit " +
                                std::to_string(kMaxModelPolygons) + ")");
  const int64_t vertices = count[0], faces = count[1];
  for (int64_t v = 0; v < vertices; ++v) {
    if (!lines.next(tok))
      fail(path, lines.line(), "the file ends after " + std::to_string(v) + " of its " + vertices_text(vertices));
    for (size_t k = 0; k < tok.size() && k < 3; ++k) check_finite(path, lines.line(), v, tok[k]);
  }
  for (int64_t f = 0; f < faces; ++f) {
    if (!lines.next(tok))
      fail(path, lines.line(), "the file ends after " + std::to_string(f) + " of its " + std::to_string(faces) + " faces");
    int64_t corners = 0;
    if (!parse_integer(tok[0], corners) || corners < 1)
      fail(path, lines.line(), "face size '" + std::string(tok[0]) + "' is not a positive integer");
    if (corners > kMaxOffFaceCorners)
      fail(path, lines.line(),
           "a face of " + std::to_string(corners) + " corners: the OFF reader (assimp) takes at most " +
               std::to_string(kMaxOffFaceCorners) + " (split it, or use OBJ or PLY)");
    if (static_cast<int64_t>(tok.size()) - 1 < corners)
      fail(path, lines.line(),
           "face lists " + std::to_string(tok.size() - 1) + " of its " + std::to_string(corners) + " vertex indices");
    for (int64_t k = 1; k <= corners; ++k) {
      int64_t i = 0;
      if (!parse_integer(tok[static_cast<size_t>(k)], i) || i < 0 || i >= vertices)
        fail(path, lines.line(),
             "vertex index " + std::string(tok[static_cast<size_t>(k)]) + " is out of range (the file has " +
                 vertices_text(vertices) + ", counted from 0)");
    }
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

}  // namespace

bool is_checked_model_format(const std::string& lower_ext) {
  return lower_ext == ".obj" || lower_ext == ".off" || lower_ext == ".ply" || lower_ext == ".stl";
}

void precheck_model(const std::string& path, const std::string& lower_ext, uint64_t size) {
  if (lower_ext == ".obj") precheck_obj(path);
  if (lower_ext == ".off") precheck_off(path, size);
  if (lower_ext == ".ply") precheck_ply(path, size);
  if (lower_ext == ".stl") precheck_stl(path, size);
}

}  // namespace girtd
