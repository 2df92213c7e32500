// PLY before assimp: the header's element counts against the file size, then
// every element instance walked as assimp will read it (ASCII: one instance
// per line; binary: packed values), so that each list length is checked
// (at most kMaxPolygonVertices, and no more values than the line or the
// bytes left hold) before assimp allocates for it. Face indices are checked
// against the vertex count; ASCII errors carry their line.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>
#include <vector>

#include "common/input_error.hpp"
#include "io/model_import.hpp"
#include "io/model_precheck.hpp"
#include "io/model_tokens.hpp"

namespace girtd {
namespace {


struct PlyType {
  int size = 0;  // bytes in a binary file
  bool integer = false, is_signed = false;
};

bool ply_type(std::string_view name, PlyType& out) {
  struct Named {
    const char* name;
    PlyType type;
  };
  constexpr Named kTypes[] = {
      {"char", {1, true, true}},     {"int8", {1, true, true}},     {"uchar", {1, true, false}},
      {"uint8", {1, true, false}},   {"short", {2, true, true}},    {"int16", {2, true, true}},
      {"ushort", {2, true, false}},  {"uint16", {2, true, false}},  {"int", {4, true, true}},
      {"int32", {4, true, true}},    {"uint", {4, true, false}},    {"uint32", {4, true, false}},
      {"float", {4, false, true}},   {"float32", {4, false, true}}, {"double", {8, false, true}},
      {"float64", {8, false, true}},
  };
  for (const Named& t : kTypes)
    if (name == t.name) {
      out = t.type;
      return true;
    }
  return false;
}

struct PlyProperty {
  std::string name;
  PlyType type;           // the value's (a list's items')
  bool is_list = false;
  PlyType count_type;     // a list's length
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
  bool face_indices(const PlyProperty& p) const {
    return name == "face" && p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
  }
};

enum class PlyFormat { kAscii, kLittleEndian, kBigEndian };

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  uint64_t vertices = 0;  // the count of element "vertex"
  size_t body = 0;        // byte offset of the first byte after end_header's line
  int body_line = 0;      // the line the body starts on
};

// The face element: one vertex index list and no other list (assimp 5.2.5
// reads a face without an index list, and a texture-coordinate list longer
// than twice the corners, past the end of its arrays).
void check_faces_element(const std::string& path, int line, const PlyHeader& h) {
  for (const PlyElement& e : h.elements) {
    if (e.name != "face") continue;
    int index_lists = 0;
    for (const PlyProperty& p : e.properties) {
      if (e.face_indices(p)) ++index_lists;
      else if (p.is_list)
        fail(path, line, "element face has the list '" + p.name + "' (assimp 5.2.5 reads such lists unchecked): only "
                             "vertex_indices is read");
    }
    if (index_lists != 1) fail(path, line, "element face needs one vertex_indices list, not " + std::to_string(index_lists));
  }
}

PlyHeader read_header(const std::string& path, const std::string& data) {
  PlyHeader h;
  bool have_format = false;
  size_t at = 0;
  std::vector<std::string_view> tok;
  for (int no = 1;; ++no) {
    if (at >= data.size()) fail(path, no, "PLY header without end_header");
    size_t end = data.find('\n', at);
    if (end == std::string::npos) end = data.size();
    std::string_view line(data.data() + at, end - at);
    at = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (no == 1) {
      if (line != "ply") fail(path, 1, "not a PLY file (the first line is not 'ply')");
      continue;
    }
    split_tokens(line, tok);
    // assimp 5.2.5 looks for the format on line 2 only (PlyLoader).
    if (no == 2 && (tok.empty() || tok[0] != "format"))
      fail(path, 2, "the second line must be 'format ...' (assimp 5.2.5 reads it there only)");
    if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "end_header") {
      if (!have_format) fail(path, no, "PLY header without a 'format' line");
      check_faces_element(path, no, h);
      h.body = std::min(at, data.size());
      h.body_line = no + 1;
      return h;
    }
    if (tok[0] == "format") {
      // assimp 5.2.5 reads the format on line 2; a second `format` line sends
      // its header reader astray (gigabytes allocated, or a refusal that
      // leaks: testbench/fuzz/regressions/ply).
      if (have_format) fail(path, no, "a second 'format' line (the format is given once, on line 2)");
      if (tok.size() < 2) fail(path, no, "'format' without a format");
      if (tok[1] == "ascii") h.format = PlyFormat::kAscii;
      else if (tok[1] == "binary_little_endian") h.format = PlyFormat::kLittleEndian;
      else if (tok[1] == "binary_big_endian") h.format = PlyFormat::kBigEndian;
      else fail(path, no, "unknown PLY format '" + std::string(tok[1]) + "'");
      have_format = true;
    } else if (tok[0] == "element") {
      int64_t n = 0;
      const std::string count = tok.size() > 2 ? std::string(tok[2]) : "";
      const std::string name = tok.size() > 1 ? std::string(tok[1]) : "";
      if (!parse_integer(count, n) || n < 0)
        fail(path, no, "PLY element '" + name + "' count '" + count + "' is not a non-negative integer");
      if (static_cast<uint64_t>(n) > data.size())
        fail(path, no,
             "header claims " + count + " " + name + " elements, more than the file's " + std::to_string(data.size()) +
                 " bytes could hold");
      // assimp 5.2.5 keeps only the last triangle of each strip (PlyLoader's
      // tristrip loop writes every triangle to the same face).
      if (name == "tristrips") fail(path, no, "triangle strips ('element tristrips') are not read: write faces instead");
      if (name == "face" && static_cast<uint64_t>(n) > kMaxModelPolygons)
        fail(path, no, "header claims " + count + " faces (limit " + std::to_string(kMaxModelPolygons) + ")");
      // assimp 5.2.5 sizes its arrays from the first vertex or face element
      // and writes every later one's past their end (PlyLoader).
      for (const PlyElement& e : h.elements)
        if ((name == "vertex" || name == "face") && e.name == name)
          fail(path, no, "a second '" + name + "' element (assimp 5.2.5 overruns its arrays on it)");
      if (name == "face" && std::none_of(h.elements.begin(), h.elements.end(), [](const PlyElement& e) { return e.name == "vertex"; }))
        fail(path, no, "'element face' before 'element vertex' (assimp 5.2.5 refuses it)");
      if (name == "vertex") h.vertices = static_cast<uint64_t>(n);
      h.elements.push_back({name, static_cast<uint64_t>(n), {}});
    } else if (tok[0] == "property") {
      if (h.elements.empty()) fail(path, no, "'property' before any 'element'");
      PlyProperty p;
      const bool list = tok.size() > 1 && tok[1] == "list";
      if (tok.size() != (list ? 5u : 3u))
        fail(path, no, list ? "expected 'property list COUNT_TYPE ITEM_TYPE NAME'" : "expected 'property TYPE NAME'");
      p.is_list = list;
      p.name = std::string(tok.back());
      const std::string_view type = tok[list ? 3 : 1];
      if (!ply_type(type, p.type)) fail(path, no, "unknown PLY type '" + std::string(type) + "'");
      if (list && (!ply_type(tok[2], p.count_type) || !p.count_type.integer))
        fail(path, no, "a list's length type must be an integer type, not '" + std::string(tok[2]) + "'");
      h.elements.back().properties.push_back(p);
    } else {
      fail(path, no, "'" + std::string(tok[0]) + "' is not a PLY header line (format, element, property, comment, "
                         "obj_info, end_header)");
    }
  }
}

// An ASCII integer as assimp 5.2.5 reads it into `t`: no sign on an
// unsigned type (strtoul10 stops there without moving on, and the rest of
// the line slides), and within the type's range (strtol10 wraps).
bool integer_fits(std::string_view v, const PlyType& t) {
  int64_t n = 0;
  if (!parse_integer(v, n) || (!t.is_signed && (v[0] == '-' || v[0] == '+'))) return false;
  const int bits = 8 * t.size;
  return t.is_signed ? n >= -(int64_t{1} << (bits - 1)) && n < (int64_t{1} << (bits - 1)) : n < (int64_t{1} << bits);
}

std::string where(const PlyElement& e, uint64_t i) { return "element '" + e.name + "' " + std::to_string(i); }

// ASCII: an instance per line (blank lines skipped, as assimp does).
// Returns the polygons (face lists of 3 or more indices) the file holds.
uint64_t walk_ascii(const std::string& path, const std::string& data, const PlyHeader& h) {
  uint64_t polygons = 0;
  size_t at = h.body;
  int no = h.body_line - 1;
  std::vector<std::string_view> tok;
  // One instance a line. assimp 5.2.5 skips neither a comment line nor
  // (after the first) a blank one here: it would read them as instances.
  auto next_line = [&]() {
    if (at >= data.size()) return false;
    size_t end = data.find('\n', at);
    if (end == std::string::npos) end = data.size();
    split_tokens(std::string_view(data.data() + at, end - at), tok);
    at = end + 1;
    ++no;
    if (tok.empty() || tok[0] == "comment")
      fail(path, no, "a blank or comment line among the elements (assimp 5.2.5 would read it as one)");
    return true;
  };
  for (const PlyElement& e : h.elements)
    for (uint64_t i = 0; i < e.count; ++i) {
      if (!next_line()) fail(path, no, "the file ends before " + where(e, i) + " (of " + std::to_string(e.count) + ")");
      size_t t = 0;
      auto value = [&](const char* what) {
        if (t >= tok.size()) fail(path, no, where(e, i) + " has too few values (missing " + what + ")");
        return tok[t++];
      };
      for (const PlyProperty& p : e.properties) {
        if (!p.is_list) {
          const std::string_view v = value(p.name.c_str());
          double d = 0;
          // assimp 5.2.5 throws a parse error naming no line (and leaks) on a value that is no number.
          if (p.type.integer ? !integer_fits(v, p.type) : !parse_real(v, d))
            fail(path, no, where(e, i) + ": '" + std::string(v) + "' is not " +
                               (p.type.integer ? "an integer of its type" : "a number") + " (property " + p.name + ")");
          if (e.name == "vertex" && (p.name == "x" || p.name == "y" || p.name == "z") && !std::isfinite(d))
            fail(path, no, "vertex " + std::to_string(i) + " has a coordinate that is NaN or infinite");
          if (!p.type.integer) check_assimp_real(path, no, v);
          continue;
        }
        int64_t n = 0;
        const std::string_view count = value(p.name.c_str());
        if (!integer_fits(count, p.count_type) || !parse_integer(count, n) || n < 0)
          fail(path, no, where(e, i) + ": list length '" + std::string(count) + "' is not a non-negative integer");
        if (static_cast<uint64_t>(n) > kMaxPolygonVertices)
          fail(path, no,
               where(e, i) + " lists " + std::to_string(n) + " values (limit " + std::to_string(kMaxPolygonVertices) +
                   ")");
        if (static_cast<uint64_t>(n) > tok.size() - t)
          fail(path, no,
               where(e, i) + " claims " + std::to_string(n) + " values but its line has " +
                   std::to_string(tok.size() - t));
        if (e.face_indices(p) && n >= 3) ++polygons;
        for (int64_t k = 0; k < n; ++k) {
          const std::string_view v = tok[t++];
          int64_t idx = 0;
          if (e.face_indices(p) &&
              (!integer_fits(v, p.type) || !parse_integer(v, idx) || idx < 0 || static_cast<uint64_t>(idx) >= h.vertices))
            fail(path, no,
                 "vertex index " + std::string(v) + " is out of range (the file has " + std::to_string(h.vertices) +
                     " vertices, counted from 0)");
        }
      }
    }
  return polygons;
}

// Binary: values packed in the file's byte order.
class BinaryWalk {
 public:
  BinaryWalk(const std::string& path, const std::string& data, const PlyHeader& h)
      : path_(path), data_(data), at_(h.body), big_(h.format == PlyFormat::kBigEndian) {}

  // Returns the polygons (face lists of 3 or more indices) the file holds.
  uint64_t run(const PlyHeader& h) {
    for (const PlyElement& e : h.elements) {
      bool lists = false;
      uint64_t row = 0;
      for (const PlyProperty& p : e.properties) {
        lists |= p.is_list;
        row += static_cast<uint64_t>(p.type.size);
      }
      if (!lists && e.name != "vertex") {  // fixed-size instances: one check for all of them
        if (e.count > 0 && row > left() / e.count)
          fail_at(at_, "the file ends inside element '" + e.name + "' (" + std::to_string(e.count) + " x " +
                           std::to_string(row) + " bytes from here, " + std::to_string(left()) + " left)");
        at_ += e.count * row;
        continue;
      }
      for (uint64_t i = 0; i < e.count; ++i)
        for (const PlyProperty& p : e.properties) instance_value(h, e, i, p);
    }
    return polygons_;
  }

 private:
  uint64_t left() const { return data_.size() - at_; }

  [[noreturn]] void fail_at(uint64_t offset, const std::string& what) const {
    throw InputError::at_byte(path_, offset, what);
  }

  void need(uint64_t bytes, const PlyElement& e, uint64_t i) const {
    if (bytes > left())
      fail_at(at_, "the file ends inside " + where(e, i) + " (" + std::to_string(bytes) + " bytes needed, " +
                       std::to_string(left()) + " left)");
  }

  // A float32 or float64 at the cursor (which stays).
  double real(const PlyType& t) const {
    uint64_t u = 0;
    for (int k = 0; k < t.size; ++k) {
      const int b = big_ ? k : t.size - 1 - k;
      u = (u << 8) | static_cast<unsigned char>(data_[at_ + static_cast<size_t>(b)]);
    }
    if (t.size == 4) {
      float f = 0;
      const uint32_t bits = static_cast<uint32_t>(u);
      std::memcpy(&f, &bits, sizeof f);
      return f;
    }
    double d = 0;
    std::memcpy(&d, &u, sizeof d);
    return d;
  }

  // An integer value at the cursor (which moves past it).
  int64_t integer(const PlyType& t) {
    uint64_t u = 0;
    for (int k = 0; k < t.size; ++k) {
      const int b = big_ ? k : t.size - 1 - k;
      u = (u << 8) | static_cast<unsigned char>(data_[at_ + static_cast<size_t>(b)]);
    }
    at_ += static_cast<uint64_t>(t.size);
    if (t.is_signed && t.size < 8 && (u >> (8 * t.size - 1)) != 0) return static_cast<int64_t>(u) - (int64_t{1} << (8 * t.size));
    return static_cast<int64_t>(u);
  }

  void instance_value(const PlyHeader& h, const PlyElement& e, uint64_t i, const PlyProperty& p) {
    if (!p.is_list) {
      need(static_cast<uint64_t>(p.type.size), e, i);
      if (e.name == "vertex" && (p.name == "x" || p.name == "y" || p.name == "z") && !p.type.integer &&
          !std::isfinite(real(p.type)))
        fail_at(at_, "vertex " + std::to_string(i) + " has a coordinate that is NaN or infinite");
      at_ += static_cast<uint64_t>(p.type.size);
      return;
    }
    need(static_cast<uint64_t>(p.count_type.size), e, i);
    const uint64_t count_at = at_;
    const int64_t n = integer(p.count_type);
    if (n < 0 || static_cast<uint64_t>(n) > kMaxPolygonVertices)
      fail_at(count_at, where(e, i) + " lists " + std::to_string(n) + " values (limit " +
                            std::to_string(kMaxPolygonVertices) + ")");
    const uint64_t bytes = static_cast<uint64_t>(n) * static_cast<uint64_t>(p.type.size);
    if (bytes > left())
      fail_at(count_at, where(e, i) + " lists " + std::to_string(n) + " values: " + std::to_string(bytes) +
                            " bytes, but " + std::to_string(left()) + " are left");
    if (!e.face_indices(p) || !p.type.integer) {
      at_ += bytes;
      return;
    }
    if (n >= 3) ++polygons_;
    for (int64_t k = 0; k < n; ++k) {
      const uint64_t index_at = at_;
      const int64_t idx = integer(p.type);
      if (idx < 0 || static_cast<uint64_t>(idx) >= h.vertices)
        fail_at(index_at, where(e, i) + ": vertex index " + std::to_string(idx) + " is out of range (the file has " +
                              std::to_string(h.vertices) + " vertices, counted from 0)");
    }
  }

  const std::string& path_;
  const std::string& data_;
  uint64_t at_;
  bool big_;
  uint64_t polygons_ = 0;
};

}  // namespace

uint64_t precheck_ply(const std::string& path, const std::string& data) {
  const PlyHeader h = read_header(path, data);
  const bool ascii = h.format == PlyFormat::kAscii;
  if (const int line = odd_line_end(std::string_view(data).substr(0, ascii ? data.size() : h.body)))
    fail(path, line, kOddLineEnd);
  // assimp 5.2.5 drops a binary body's first byte when it is a line feed
  // (PlyParser: "remove first char if it's /n"), and reads every value after
  // it shifted. A header ending in CR LF is read as usual.
  if (!ascii && h.body < data.size() && data[h.body] == '\n' && h.body >= 2 && data[h.body - 2] != '\r')
    throw InputError::at_byte(path, h.body,
                              "the first data byte is 0x0A, which assimp 5.2.5 drops (every value after it would be "
                              "read shifted): end the header's lines with CR LF to keep it");
  return ascii ? walk_ascii(path, data, h) : BinaryWalk(path, data, h).run(h);
}

}  // namespace girtd
