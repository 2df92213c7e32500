#include "io/model_precheck.hpp"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <fstream>
#include <string_view>
#include <vector>

#include "common/input_error.hpp"
#include "io/model_import.hpp"
#include "io/model_tokens.hpp"

namespace girtd {
namespace {
namespace fs = std::filesystem;

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

// The statements of an OBJ file as assimp 5.2.5 reads them: a line ending
// in '\' is joined to the next with nothing in between (IOStreamBuffer::
// getNextDataLine), and a statement keeps the line it starts on.
class ObjStatements {
 public:
  // `warnings`, when given, is told of a continuation that glues two tokens.
  explicit ObjStatements(const std::string& path, std::vector<std::string>* warnings = nullptr)
      : path_(path), in_(path, std::ios::binary), warnings_(warnings) {}
  bool next(std::string& statement) {
    if (!std::getline(in_, line_)) return false;
    start_ = ++no_;
    statement.clear();
    for (;;) {
      if (!line_.empty() && line_.back() == '\r') line_.pop_back();
      if (line_.empty() || line_.back() != '\\') {
        statement += line_;
        return true;
      }
      line_.pop_back();
      statement += line_;
      const bool glued_before = !line_.empty() && !std::isspace(static_cast<unsigned char>(line_.back()));
      if (!std::getline(in_, line_)) return true;
      ++no_;
      if (warnings_ && glued_before && !line_.empty() && !std::isspace(static_cast<unsigned char>(line_[0])))
        warnings_->push_back(path_ + ":" + std::to_string(no_ - 1) +
                             ": a '\\' continuation with no space on either side joins two tokens into one (as "
                             "assimp 5.2.5 reads it: \"1\\\" + \"2\" is 12)");
      // assimp copies the first character after the joined line end unchecked:
      // an empty line there swallows the statement after it.
      if (line_.empty() || line_ == "\r")
        fail(path_, no_, "a '\\' continuation runs into an empty line (assimp 5.2.5 would lose the next statement)");
    }
  }
  int line() const { return start_; }

 private:
  const std::string& path_;
  std::ifstream in_;
  std::vector<std::string>* warnings_;
  std::string line_;
  int no_ = 0, start_ = 0;
};

// An index assimp 5.2.5 reads as an extra corner: a leading '+' or '0'
// ("+2", "01", "-02"; ObjFileParser::getFace steps by the value's digits,
// not the token's).
bool misread_index(std::string_view part) {
  if (!part.empty() && part[0] == '+') return true;
  const std::string_view digits = part.substr(!part.empty() && part[0] == '-' ? 1 : 0);
  return digits.size() > 1 && digits[0] == '0';
}

// Material libraries and names: materials in model files are not used (the
// model is drawn with the scene's or the default material), so what is
// missing is a warning, never an error. assimp is not let read them at all.
class ObjMaterials {
 public:
  ObjMaterials(const std::string& path, std::vector<std::string>& warnings) : path_(path), warnings_(warnings) {}
  void library(int line, const std::string& name) {
    const fs::path lib = fs::path(path_).parent_path() / name;
    std::ifstream in(lib, std::ios::binary);
    if (!in) {
      warn(line, "material library '" + name + "' not found");
      return;
    }
    ++libraries_;
    std::string text;
    std::vector<std::string_view> tok;
    while (std::getline(in, text)) {
      split_tokens(text, tok);
      if (tok.size() >= 2 && tok[0] == "newmtl") defined_.insert(rest_of(text, "newmtl"));
    }
  }
  void use(int line, const std::string& name) {
    if (defined_.count(name) || !reported_.insert(name).second) return;
    if (libraries_ > 0) warn(line, "usemtl '" + name + "' names no material of the file's material libraries");
    else if (!missing_library_reported_) warn(line, "usemtl '" + name + "' without a material library");
  }
  // The text after `keyword`, trimmed (names may hold spaces).
  static std::string rest_of(std::string_view statement, std::string_view keyword) {
    size_t a = statement.find(keyword) + keyword.size();
    while (a < statement.size() && std::isspace(static_cast<unsigned char>(statement[a]))) ++a;
    size_t b = statement.find('#', a) == std::string_view::npos ? statement.size() : statement.find('#', a);
    while (b > a && std::isspace(static_cast<unsigned char>(statement[b - 1]))) --b;
    return std::string(statement.substr(a, b - a));
  }

 private:
  void warn(int line, const std::string& what) {
    missing_library_reported_ = true;
    warnings_.push_back(path_ + ":" + std::to_string(line) + ": " + what +
                        " (materials in model files are not used: drawn with the scene's or the default material)");
  }
  const std::string& path_;
  std::vector<std::string>& warnings_;
  int libraries_ = 0;
  bool missing_library_reported_ = false;
  std::set<std::string> defined_, reported_;
};

// OBJ: no counts to trust; two passes find the line of a vertex with a NaN
// coordinate and of a face whose index is 0 or out of range (positive
// indices may point forward, as assimp allows; negative ones count back
// from the vertices read so far), and refuse what assimp 5.2.5 would read
// silently wrong. Returns the polygons (faces of 3 or more corners).
uint64_t precheck_obj(const std::string& path, std::vector<std::string>& warnings) {
  std::vector<std::string_view> tok;
  std::string st;
  int64_t total = 0;
  {
    std::ifstream in(path, std::ios::binary);
    char bom[3] = {};
    in.read(bom, 3);
    if (in.gcount() == 3 && bom[0] == '\xEF' && bom[1] == '\xBB' && bom[2] == '\xBF')
      fail(path, 1, "the file starts with a UTF-8 byte-order mark (assimp 5.2.5 would lose its first statement)");
    ObjStatements statements(path);
    while (statements.next(st)) {
      const int no = statements.line();
      split_tokens(st, tok);
      if (tok.empty()) continue;
      if (st[0] == ' ' || st[0] == '\t')
        fail(path, no, "an indented statement (assimp 5.2.5 skips it): remove the leading white space");
      if (tok[0] != "v") continue;
      ++total;
      const size_t n = tok.size() - 1;
      if (n != 3 && n != 4 && n != 6)
        fail(path, no, "a vertex of " + std::to_string(n) + " numbers (assimp 5.2.5 reads x y z, x y z w or x y z r g b)");
      for (size_t k = 1; k < tok.size(); ++k) {
        if (tok[k][0] == '.')  // ObjTools' IsNumeric: not a number
          fail(path, no, "'" + std::string(tok[k]) + "' (assimp 5.2.5 skips a number that starts with '.': write 0" +
                             std::string(tok[k]) + ")");
        if (k <= 3) check_finite(path, no, total, tok[k]);
      }
    }
  }
  ObjStatements statements(path, &warnings);
  ObjMaterials materials(path, warnings);
  int64_t seen = 0;
  uint64_t polygons = 0;
  while (statements.next(st)) {
    const int no = statements.line();
    split_tokens(st, tok);
    if (tok.empty()) continue;
    if (tok[0] == "v") ++seen;
    if (tok[0] == "mtllib" && tok.size() >= 2) materials.library(no, ObjMaterials::rest_of(st, "mtllib"));
    if (tok[0] == "usemtl" && tok.size() >= 2) materials.use(no, ObjMaterials::rest_of(st, "usemtl"));
    if (tok[0] != "f") continue;
    if (tok.size() >= 4) ++polygons;
    for (size_t k = 1; k < tok.size(); ++k) {
      std::string_view corner = tok[k];
      for (size_t at = 0; at <= corner.size();) {  // v/vt/vn, each may be empty
        const size_t slash = std::min(corner.find('/', at), corner.size());
        const std::string_view part = corner.substr(at, slash - at);
        if (misread_index(part))
          fail(path, no, "index '" + std::string(part) + "' (assimp 5.2.5 reads a leading '0' or '+' as an extra corner)");
        at = slash + 1;
      }
      int64_t i = 0;
      if (!parse_leading_integer(corner, i)) continue;  // assimp's to judge
      if (i == 0) fail(path, no, "vertex index 0 is out of range (OBJ counts from 1)");
      if (i > total || (i < 0 && seen + i < 0))
        fail(path, no,
             "vertex index " + std::to_string(i) + " is out of range (" +
                 (i > 0 ? "the file has " + vertices_text(total) : vertices_text(seen) + " so far") + ")");
    }
  }
  return polygons;
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
// its indices, NaN coordinates. Returns the polygons (faces of 3 or more corners).
uint64_t precheck_off(const std::string& path, uint64_t size) {
  OffLines lines(path);
  std::vector<std::string_view> tok;
  if (!lines.next(tok)) fail(path, 0, "OFF file without vertex and face counts");
  // The header's tokens after the keyword ([dimension], vertices, faces,
  // edges), read across lines as assimp does, with their lines.
  const bool keyword = tok[0].size() >= 3 && tok[0].substr(tok[0].size() - 3) == "OFF";
  const bool dimension = keyword && tok[0].find('n') != std::string_view::npos;
  const bool coff = tok[0] == "COFF";
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
  uint64_t polygons = 0;
  for (int64_t v = 0; v < vertices; ++v) {
    if (!lines.next(tok))
      fail(path, lines.line(), "the file ends after " + std::to_string(v) + " of its " + vertices_text(vertices));
    for (size_t k = 0; k < tok.size() && k < 3; ++k) check_finite(path, lines.line(), v, tok[k]);
    // COFF colours are RGBA; assimp 5.2.5 throws a cryptic parse error on fewer.
    if (coff && tok.size() < 7)
      fail(path, lines.line(), "a COFF vertex is x y z and 4 colour values (RGBA); this one has " +
                                   std::to_string(tok.size()) + " numbers");
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
    if (corners >= 3) ++polygons;
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
  return polygons;
}

// Returns the triangles: a binary file's count, an ASCII file's facets.
// Binary or ASCII is told as assimp 5.2.5 tells it (STLLoader's IsBinarySTL
// first): binary when the size is 84 + 50 x the count at byte 80, whatever
// the header's text ("solid" starts many binary headers), else ASCII when it
// starts with "solid".
uint64_t precheck_stl(const std::string& path, uint64_t size) {
  std::ifstream in(path, std::ios::binary);
  char head[84] = {};
  in.read(head, sizeof head);
  uint32_t n = 0;
  for (int i = 3; i >= 0; --i) n = (n << 8) | static_cast<unsigned char>(head[80 + i]);
  const bool binary = in.gcount() == 84 && 84 + 50 * uint64_t{n} == size;
  if (!binary && std::string(head, 5) == "solid") {
    std::ifstream text(path, std::ios::binary);
    std::string line;
    std::vector<std::string_view> tok;
    uint64_t facets = 0;
    while (std::getline(text, line)) {
      split_tokens(line, tok);
      if (!tok.empty() && tok[0] == "facet") ++facets;
    }
    return facets;
  }
  if (in.gcount() < 84)
    throw InputError::at_byte(path, static_cast<uint64_t>(in.gcount()),
                              "binary STL shorter than its 84-byte header (80 bytes of text, a 4-byte triangle count)");
  if (!binary)
    throw InputError::at_byte(path, 80,
                              "binary STL claims " + std::to_string(n) + " triangles (" +
                                  std::to_string(84 + 50 * uint64_t{n}) + " bytes) but the file has " +
                                  std::to_string(size) + " bytes");
  return n;
}

}  // namespace

bool is_checked_model_format(const std::string& lower_ext) {
  return lower_ext == ".obj" || lower_ext == ".off" || lower_ext == ".ply" || lower_ext == ".stl";
}

uint64_t precheck_model(const std::string& path, const std::string& lower_ext, uint64_t size,
                        std::vector<std::string>& warnings) {
  if (lower_ext == ".obj") return precheck_obj(path, warnings);
  if (lower_ext == ".off") return precheck_off(path, size);
  if (lower_ext == ".ply") return precheck_ply(path, size);
  return precheck_stl(path, size);
}

}  // namespace girtd
