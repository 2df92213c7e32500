#include "io/model_precheck.hpp"

#include <algorithm>
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

// assimp's OFF reader copies a line into a 4096-byte buffer and writes its
// terminator one past the end (OFFLoader's GetNextLine): a longer line
// overflows it and is read as two.
constexpr size_t kMaxOffLine = 4095;

// The OFF text line by line. Empty lines are skipped (assimp skips runs of
// line ends); inside the vertex and face lists a line of blanks or a comment
// is refused, since assimp reads it as a face of 0 corners (dropping the
// last face) or fails on it.
class OffLines {
 public:
  OffLines(const std::string& path, std::string_view text) : path_(path), text_(text) {}
  // The next line with a token; false at the end of the file.
  bool next(std::vector<std::string_view>& tok, bool in_lists) {
    while (at_ < text_.size()) {
      size_t end = text_.find('\n', at_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view line = text_.substr(at_, end - at_);
      at_ = end + 1;
      ++no_;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (line.size() > kMaxOffLine)
        fail(path_, no_, "a line of " + std::to_string(line.size()) + " bytes: assimp 5.2.5 reads at most " +
                             std::to_string(kMaxOffLine) + " (and overflows its buffer past that)");
      split_tokens(line, tok);
      if (!tok.empty()) return true;
      if (in_lists && !line.empty())
        fail(path_, no_, "a blank or comment line inside the vertex and face lists (assimp 5.2.5 reads it as a face)");
    }
    return false;
  }
  int line() const { return no_; }

 private:
  const std::string& path_;
  std::string_view text_;
  size_t at_ = 0;
  int no_ = 0;
};

// OFF counts and indices as assimp 5.2.5 reads them (strtoul10): digits
// only; it stops at a sign without moving on, so "+3" reads 0.
bool plain_digits(std::string_view t) {
  return !t.empty() && t.size() <= 18 && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// OFF: the header's counts against the file size and the limits, then every
// vertex and face line: a face's corner count (what assimp allocates from),
// its indices, NaN coordinates. Returns the polygons (faces of 3 or more corners).
uint64_t precheck_off(const std::string& path, const std::string& text) {
  const uint64_t size = text.size();
  if (const int line = odd_line_end(text)) fail(path, line, kOddLineEnd);
  OffLines lines(path, text);
  std::vector<std::string_view> tok;
  if (!lines.next(tok, false)) fail(path, 0, "OFF file without vertex and face counts");
  // The header's tokens after the keyword ([dimension], vertices, faces,
  // edges), read across lines as assimp does, with their lines.
  const bool keyword = tok[0].size() >= 3 && tok[0].substr(tok[0].size() - 3) == "OFF";
  const bool dimension = keyword && tok[0].find('n') != std::string_view::npos;
  // [ST][C][N][4][n]OFF: with C, each vertex has 4 colour values after its
  // position (and normal, and texture coordinates): assimp 5.2.5 throws a
  // parse error naming no line on fewer.
  const std::string_view prefix = keyword ? tok[0].substr(0, tok[0].size() - 3) : std::string_view();
  const size_t colour_tokens = prefix.find('C') != std::string_view::npos
                                   ? 3 + 4 + (prefix.find('N') != std::string_view::npos ? 3 : 0) +
                                         (prefix.rfind("ST", 0) == 0 ? 2 : 0)
                                   : 0;
  std::vector<std::pair<std::string, int>> header;
  const size_t wanted = 3 + (dimension ? 1 : 0);
  for (size_t at = keyword ? 1 : 0; header.size() < wanted; ++at) {
    if (at == tok.size()) {
      if (!lines.next(tok, false)) fail(path, lines.line(), "OFF file without vertex and face counts");
      at = 0;
    }
    header.emplace_back(std::string(tok[at]), lines.line());
  }
  const size_t first = dimension ? 1 : 0;
  int64_t count[2] = {0, 0};
  const int counts_line = header[first].second;
  for (size_t i = 0; i < 2; ++i) {
    const std::string& t = header[first + i].first;
    if (!plain_digits(t) || !parse_integer(t, count[i]))
      fail(path, counts_line, "OFF count '" + t + "' is not a non-negative integer");
    if (static_cast<uint64_t>(count[i]) > size)
      fail(path, counts_line,
           "header claims " + t + (i == 0 ? " vertices" : " faces") + ", more than the file's " + std::to_string(size) +
               " bytes could hold");
  }
  // The edge count is read (and ignored) by assimp as an integer: a missing
  // one takes the integer part of the first coordinate.
  int64_t edges = 0;
  if (!plain_digits(header[first + 2].first) || !parse_integer(header[first + 2].first, edges))
    fail(path, header[first + 2].second,
         "OFF edge count '" + header[first + 2].first + "' is not a non-negative integer (the header is vertices faces edges)");
  if (static_cast<uint64_t>(count[1]) > kMaxModelPolygons)
    fail(path, counts_line, "header claims " + std::to_string(count[1]) + " faces (limit " +
                                std::to_string(kMaxModelPolygons) + ")");
  const int64_t vertices = count[0], faces = count[1];
  uint64_t polygons = 0;
  for (int64_t v = 0; v < vertices; ++v) {
    if (!lines.next(tok, true))
      fail(path, lines.line(), "the file ends after " + std::to_string(v) + " of its " + vertices_text(vertices));
    if (tok.size() < 3) fail(path, lines.line(), "a vertex of " + std::to_string(tok.size()) + " numbers (x y z)");
    for (size_t k = 0; k < std::max<size_t>(3, colour_tokens) && k < tok.size(); ++k) {
      if (k < 3) check_finite(path, lines.line(), v, tok[k]);
      check_assimp_real(path, lines.line(), tok[k]);
    }
    if (tok.size() < colour_tokens)
      fail(path, lines.line(), "a " + std::string(prefix) + "OFF vertex has " +
                                   std::to_string(colour_tokens) + " numbers with its 4 colour values (RGBA); this one has " +
                                   std::to_string(tok.size()));
  }
  for (int64_t f = 0; f < faces; ++f) {
    if (!lines.next(tok, true))
      fail(path, lines.line(), "the file ends after " + std::to_string(f) + " of its " + std::to_string(faces) + " faces");
    int64_t corners = 0;
    if (!plain_digits(tok[0]) || !parse_integer(tok[0], corners) || corners < 1)
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
      if (!plain_digits(tok[static_cast<size_t>(k)]) || !parse_integer(tok[static_cast<size_t>(k)], i) || i >= vertices)
        fail(path, lines.line(),
             "vertex index " + std::string(tok[static_cast<size_t>(k)]) + " is out of range (the file has " +
                 vertices_text(vertices) + ", counted from 0)");
    }
  }
  return polygons;
}

}  // namespace

bool is_checked_model_format(const std::string& lower_ext) {
  return lower_ext == ".obj" || lower_ext == ".off" || lower_ext == ".ply" || lower_ext == ".stl";
}

std::string read_model_bytes(const std::string& path, uint64_t size) {
  std::ifstream in(path, std::ios::binary);
  std::string data(static_cast<size_t>(size), '\0');
  in.read(data.data(), static_cast<std::streamsize>(size));
  data.resize(static_cast<size_t>(in.gcount()));
  return data;
}

PrecheckResult precheck_model(const std::string& path, const std::string& lower_ext, uint64_t size,
                              std::vector<std::string>& warnings) {
  const std::string data = read_model_bytes(path, size);  // read once, for every check and count below
  if (lower_ext == ".obj") return precheck_obj(path, data, warnings);
  if (lower_ext == ".off") return {precheck_off(path, data), {}};
  if (lower_ext == ".ply") return {precheck_ply(path, data), {}};
  return {precheck_stl(path, data), {}};
}

}  // namespace girtd
