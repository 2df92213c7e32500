// The STL check: a binary file's size and coordinates; an ASCII file walked
// the way assimp 5.2.5's STLImporter::LoadASCIIFile walks it, so that every
// input on which that reader would throw (and leak the meshes it has made:
// testbench/fuzz/README.md, Findings) is refused here first, with its line.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>

#include "common/input_error.hpp"
#include "io/model_precheck.hpp"
#include "io/model_tokens.hpp"

namespace girtd {
namespace {

// assimp's AI_MAXLEN: a solid's name must be shorter.
constexpr size_t kMaxSolidName = 1024;

// A little-endian float32 at `p`.
double float_at(const char* p) {
  const uint32_t bits = u32_at(p);
  float f = 0;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// assimp's IsBinarySTL: a size of 84 + 50 x the count at byte 80, in its
// 32-bit arithmetic (a wrapped product counts).
bool looks_binary(std::string_view data) {
  return data.size() >= 84 && uint32_t{84} + uint32_t{50} * u32_at(data.data() + 80) == static_cast<uint32_t>(data.size());
}

// The byte-order marks assimp 5.2.5 converts a file from before any reader
// sees it (BaseImporter::ConvertToUTF8, binary STL included): UTF-8, UTF-16
// and UTF-32 in either order.
bool starts_with_byte_order_mark(std::string_view data) {
  for (std::string_view mark : {std::string_view("\xEF\xBB\xBF"), std::string_view("\xFF\xFE"),
                                std::string_view("\xFE\xFF"), std::string_view("\0\0\xFE\xFF", 4)})
    if (data.compare(0, mark.size(), mark) == 0) return true;
  return false;
}

// assimp's character classes (its IsSpace, IsLineEnd; the text's end reads
// as its NUL terminator). odd_line_end has refused NUL, form feed and lone CR.
bool is_space(char c) { return c == ' ' || c == '\t'; }
bool is_line_end(char c) { return c == '\n' || c == '\r' || c == '\0'; }

// A cursor over the text with assimp's moves, counting lines as it goes.
class StlText {
 public:
  StlText(const std::string& path, std::string_view text) : path_(path), text_(text) {}
  char at(size_t k = 0) const { return pos_ + k < text_.size() ? text_[pos_ + k] : '\0'; }
  bool at_end() const { return pos_ >= text_.size(); }
  bool starts(std::string_view word) const { return text_.compare(std::min(pos_, text_.size()), word.size(), word) == 0; }
  void skip(size_t n) {
    for (; n > 0; --n) step();
  }
  void skip_spaces() {
    while (is_space(at())) step();
  }
  void skip_spaces_and_line_ends() {
    while (is_space(at()) || at() == '\n' || at() == '\r') step();
  }
  // Up to the next blank or line end: a name, or a word assimp skips.
  std::string_view word() {
    const size_t start = pos_;
    while (!is_space(at()) && !is_line_end(at())) ++pos_;
    return text_.substr(std::min(start, text_.size()), pos_ - std::min(start, text_.size()));
  }
  // assimp's IsAsciiSTL on the rest: "solid" after blanks, more after it,
  // and the rest not sized like a binary file.
  bool solid_follows() const {
    const std::string_view rest = text_.substr(std::min(pos_, text_.size()));
    if (looks_binary(rest)) return false;
    const size_t first = rest.find_first_not_of(" \t");
    return first != std::string_view::npos && !is_line_end(rest[first]) && first + 5 < rest.size() &&
           rest.compare(first, 5, "solid") == 0;
  }
  int line() const { return line_; }
  [[noreturn]] void refuse(const std::string& what) const { fail(path_, line(), what); }
  [[noreturn]] void refuse_at(int line, const std::string& what) const { fail(path_, line, what); }

  // The three numbers after `facet normal` or `vertex`, on the keyword's
  // line: assimp reads each with fast_atoreal_move after skipping blanks
  // only. A number must make up its whole word, so assimp stops where this
  // check does.
  void numbers(std::string_view keyword, bool coordinates, uint64_t vertex) {
    for (int k = 0; k < 3; ++k) {
      skip_spaces();
      const std::string_view t = word();
      if (t.empty()) refuse("'" + std::string(keyword) + "' with fewer than 3 numbers on its line");
      if (coordinates) check_finite(path_, line_, static_cast<int64_t>(vertex), t);
      check_assimp_real(path_, line_, t);
    }
  }

 private:
  void step() {
    if (at() == '\n') ++line_;
    ++pos_;
  }
  const std::string& path_;
  std::string_view text_;
  size_t pos_ = 0;
  int line_ = 1;
};

// Returns the triangles. Refuses where assimp would throw, and where it would
// go on silently from something it logs (a facet of other than 3 vertices, a
// vertex outside a facet, a facet without a normal).
uint64_t precheck_ascii_stl(const std::string& path, std::string_view data) {
  if (const int line = odd_line_end(data)) fail(path, line, kOddLineEnd);
  StlText s(path, data);
  uint64_t triangles = 0;
  bool first = true;
  while (first || s.solid_follows()) {
    first = false;
    s.skip_spaces();
    s.skip(5);  // "solid"
    s.skip_spaces();
    if (s.word().size() >= kMaxSolidName)
      s.refuse("a solid's name of " + std::to_string(kMaxSolidName) + " bytes or more (assimp 5.2.5 refuses it)");
    uint64_t vertices = 0;
    int corners = 3;  // of the facet being read; assimp starts at 3, so a vertex before any facet is dropped
    int facet_line = 0;
    auto check_facet_done = [&] {
      if (corners != 3) s.refuse_at(facet_line, "a facet of " + std::to_string(corners) + " vertices, not 3");
    };
    for (;;) {
      s.skip_spaces_and_line_ends();
      if (s.at_end()) break;  // assimp warns of the missing `endsolid` and goes on
      if (s.starts("facet") && (is_space(s.at(5)) || s.at(5) == '\n' || s.at(5) == '\r')) {
        check_facet_done();
        corners = 0;
        facet_line = s.line();
        s.skip(6);
        s.skip_spaces();
        if (!s.starts("normal")) s.refuse("'facet' without 'normal' after it (assimp 5.2.5 would read no normal for it)");
        if (s.at(6) == '\0') s.refuse("the file ends inside a facet");
        s.skip(7);  // "normal" and the character after it, whatever it is
        s.numbers("facet normal", false, 0);
      } else if (s.starts("vertex") && (is_space(s.at(6)) || is_line_end(s.at(6)))) {
        if (facet_line == 0) s.refuse("a 'vertex' before any 'facet normal'");
        if (corners >= 3) {  // assimp drops it (with an error in its log): refused once the facet's count is known
          ++corners;
          s.skip(1);
          continue;
        }
        if (s.at(6) == '\0') s.refuse("the file ends inside a facet");
        s.skip(7);
        s.numbers("vertex", true, vertices);
        ++vertices;
        ++corners;
      } else if (s.starts("endsolid")) {
        do s.skip(1);
        while (!is_line_end(s.at()));
        s.skip_spaces_and_line_ends();
        // assimp reads on only if another solid follows, and drops the rest.
        if (!s.at_end() && !s.solid_follows()) s.refuse("text after 'endsolid' that is not another 'solid' (assimp 5.2.5 drops it)");
        break;
      } else {
        s.skip(1);  // assimp steps past a word it does not know: one character, then to a blank or line end
        s.word();
      }
    }
    if (facet_line != 0) check_facet_done();
    triangles += vertices / 3;
  }
  return triangles;
}

}  // namespace

// Binary or ASCII is told as assimp 5.2.5 tells it (STLLoader's IsBinarySTL
// first): binary when the size is 84 + 50 x the count at byte 80, whatever
// the header's text ("solid" starts many binary headers), else ASCII when
// it starts with "solid" after any blanks.
uint64_t precheck_stl(const std::string& path, const std::string& data) {
  const uint64_t size = data.size();
  if (size < 8) fail(path, 1, "a file of " + std::to_string(size) + " bytes (assimp 5.2.5 reads none under 8)");
  if (starts_with_byte_order_mark(data))
    fail(path, 1, "the file starts with a byte-order mark (assimp 5.2.5 converts the whole file, a binary one too, from it)");
  const bool binary = looks_binary(data);
  const size_t text_start = data.find_first_not_of(" \t");
  if (!binary && text_start != std::string::npos && data.compare(text_start, 5, "solid") == 0)
    return precheck_ascii_stl(path, data);
  if (size < 84)
    throw InputError::at_byte(path, size,
                              "binary STL shorter than its 84-byte header (80 bytes of text, a 4-byte triangle count)");
  const uint32_t n = u32_at(data.data() + 80);
  if (84 + 50 * uint64_t{n} != size)
    throw InputError::at_byte(path, 80,
                              "binary STL claims " + std::to_string(n) + " triangles (" +
                                  std::to_string(84 + 50 * uint64_t{n}) + " bytes) but the file has " +
                                  std::to_string(size) + " bytes");
  // Each triangle: normal (12 bytes), 3 corners (36), attribute (2).
  for (uint64_t t = 0; t < n; ++t)
    for (int c = 0; c < 9; ++c) {
      const uint64_t at = 84 + 50 * t + 12 + 4 * static_cast<uint64_t>(c);
      if (!std::isfinite(float_at(data.data() + at)))
        throw InputError::at_byte(path, at,
                                  "triangle " + std::to_string(t) + " corner " + std::to_string(c / 3) +
                                      " has a coordinate that is NaN or infinite");
    }
  return n;
}

}  // namespace girtd
