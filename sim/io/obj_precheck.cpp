// OBJ before assimp: no counts to trust, so the check reads every statement
// that makes geometry (v, f) as the OBJ format means it, and refuses, with
// its line, whatever Debian's assimp 5.2.5 would read differently: some of
// it silently (a dropped vertex shifts every later index), some of it with
// an error that names no line. Each rule names the assimp code it guards;
// sim/io/README.md has the table.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>
#include <vector>

#include "io/model_precheck.hpp"
#include "io/model_tokens.hpp"

namespace girtd {
namespace {
namespace fs = std::filesystem;

// Statements whose lines assimp joins at a trailing '\' (IOStreamBuffer::
// getNextDataLine); it joins any line, so on another statement (a comment,
// a group name) the next statement is swallowed.
bool joinable(std::string_view keyword) {
  return keyword == "v" || keyword == "vt" || keyword == "vn" || keyword == "f" || keyword == "l" || keyword == "p";
}

// The statements of an OBJ text: a line ending in '\' joined to the next,
// as assimp joins them, and each statement with the line it starts on.
class ObjStatements {
 public:
  ObjStatements(const std::string& path, std::string_view text) : path_(path), text_(text) {}

  bool next(std::string& statement) {
    if (at_ >= text_.size()) return false;
    start_ = ++no_;
    statement.clear();
    for (;;) {
      std::string_view line = take_line();
      if (line.empty() || line.back() != '\\') {
        statement += line;
        return true;
      }
      line.remove_suffix(1);
      statement += line;
      std::vector<std::string_view> tok;
      split_tokens(statement, tok);
      if (tok.empty() || !joinable(tok[0]))
        fail(path_, no_, "a '\\' at the end of a comment or a '" + std::string(tok.empty() ? "" : tok[0]) +
                             "' line: assimp 5.2.5 would join the next line to it and lose that statement");
      if (at_ >= text_.size()) return true;
      const std::string_view next_line = peek_line();
      // assimp copies the first character after the joined line end unchecked.
      if (next_line.empty() || next_line[0] == '\\')
        fail(path_, no_ + 1, "a '\\' continuation runs into an empty line or another '\\' (assimp 5.2.5 would lose "
                             "what follows)");
      // assimp puts nothing between the joined lines: "1\" + "2" reads 12.
      if (!line.empty() && !is_space(line.back()) && !is_space(next_line[0]))
        fail(path_, no_, "a '\\' continuation with no space on either side: assimp 5.2.5 joins '" +
                             std::string(last_token(line)) + "' and '" + std::string(first_token(next_line)) +
                             "' into one number");
      ++no_;
    }
  }
  int line() const { return start_; }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t'; }
  static std::string_view last_token(std::string_view s) {
    const size_t b = s.find_last_of(" \t");
    return b == std::string_view::npos ? s : s.substr(b + 1);
  }
  static std::string_view first_token(std::string_view s) { return s.substr(0, s.find_first_of(" \t")); }
  std::string_view peek_line() const {
    size_t end = text_.find('\n', at_);
    if (end == std::string_view::npos) end = text_.size();
    std::string_view line = text_.substr(at_, end - at_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
  }
  std::string_view take_line() {
    const std::string_view line = peek_line();
    const size_t end = text_.find('\n', at_);
    at_ = end == std::string_view::npos ? text_.size() : end + 1;
    return line;
  }

  const std::string& path_;
  std::string_view text_;
  size_t at_ = 0;
  int no_ = 0, start_ = 0;
};

// A number as assimp 5.2.5 counts one in a vertex: ObjTools' IsNumeric
// looks at the first character only, a digit, '-' or '+' (whether fast_atof
// then reads the rest right is check_assimp_real's question).
bool assimp_number(std::string_view t) {
  return !t.empty() && (std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '-' || t[0] == '+');
}

// An index part of a face corner: empty (v//vn) or a non-zero int as
// assimp 5.2.5 reads it. ObjFileParser::getFace steps by the value's
// digits, not the token's, so "01", "+2" and "-02" read as an extra corner,
// and a value past INT_MAX wraps negative and takes the next corner with it.
bool index_part_ok(std::string_view part) {
  if (part.empty()) return true;
  const std::string_view digits = part.substr(part[0] == '-' ? 1 : 0);
  if (digits.empty() || digits.size() > 10 || digits[0] == '0') return false;
  if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) return false;
  int64_t value = 0;
  return read_integer(digits, value) == NumberRead::kOk && value <= 2147483647;
}

// The text after `keyword`, trimmed (names may hold spaces).
std::string rest_of(std::string_view statement, std::string_view keyword) {
  size_t a = statement.find(keyword) + keyword.size();
  while (a < statement.size() && std::isspace(static_cast<unsigned char>(statement[a]))) ++a;
  size_t b = std::min(statement.find('#', a), statement.size());
  while (b > a && std::isspace(static_cast<unsigned char>(statement[b - 1]))) --b;
  return std::string(statement.substr(a, b - a));
}

// Material libraries and names: a missing library or material leaves its
// faces with the default material, so it is a warning, never an error. The
// libraries read here are the ones assimp reads next (regular files only).
class ObjMaterials {
 public:
  ObjMaterials(const std::string& path, std::vector<std::string>& warnings) : path_(path), warnings_(warnings) {}

  // "mtllib a.mtl b.mtl": several libraries, or one name with spaces.
  void libraries(int line, const std::string& names) {
    // assimp takes the whole rest of the line for one name; were it the model
    // itself, its MTL reader would run on the OBJ text (and can crash on it).
    std::error_code ec;
    if (fs::weakly_canonical(fs::path(path_).parent_path() / names, ec) == fs::weakly_canonical(path_, ec))
      fail(path_, line, "mtllib names the model file itself");
    if (read(names)) return;
    std::istringstream each(names);
    std::string name;
    bool any = false;
    while (each >> name) any |= read(name);
    if (!any) warn(line, "material library '" + names + "' not found");
  }
  void use(int line, const std::string& name) {
    used_.insert(name);
    if (defined_.count(name) || !reported_.insert(name).second) return;
    if (libraries_ > 0) warn(line, "usemtl '" + name + "' names no material of the file's material libraries");
    else if (!warned_) warn(line, "usemtl '" + name + "' without a material library");
  }
  // The names used that no library defines (once all are read).
  std::set<std::string> undefined() const {
    std::set<std::string> out;
    for (const std::string& n : used_)
      if (!defined_.count(n)) out.insert(n);
    return out;
  }

 private:
  // Reads the names a library defines (newmtl), if it is a regular file of
  // at most 16 MiB: a path may name a device or a pipe.
  bool read(const std::string& name) {
    const fs::path lib = fs::path(path_).parent_path() / name;
    std::error_code ec;
    if (!fs::is_regular_file(lib, ec) || fs::file_size(lib, ec) > (16u << 20) || ec) return false;
    std::ifstream in(lib, std::ios::binary);
    if (!in) return false;
    ++libraries_;
    std::string text;
    std::vector<std::string_view> tok;
    while (std::getline(in, text)) {
      split_tokens(text, tok);
      if (tok.size() >= 2 && tok[0] == "newmtl") defined_.insert(rest_of(text, "newmtl"));
    }
    return true;
  }
  void warn(int line, const std::string& what) {
    warned_ = true;
    warnings_.push_back(path_ + ":" + std::to_string(line) + ": " + what +
                        " (its faces are drawn with the default material)");
  }

  const std::string& path_;
  std::vector<std::string>& warnings_;
  int libraries_ = 0;
  bool warned_ = false;  // one warning for a file without libraries, not one per usemtl
  std::set<std::string> defined_, reported_, used_;
};

// A statement as assimp 5.2.5's ObjFileParser::parseFile sees it: by its
// first character alone (any word starting with 'f', 'l' or 'p' is read as
// a face, a line or a point; "v" needs a blank after it), an indented one not
// at all, and nothing between a "cstype" line and an "end" line (free-form
// geometry is skipped whole). kind() returns 'v', 'f', 'l', 'p' or 0 and
// refuses, with the line, the statements assimp would read otherwise than
// they are written.
class AssimpView {
 public:
  char kind(const std::string& path, int line, const std::string& st, const std::vector<std::string_view>& tok) {
    if (tok.empty()) return 0;
    const bool geometry = tok[0] == "v" || tok[0] == "f";
    if (in_cstype_) {
      if (st[0] == 'e' && tok[0] == "end") in_cstype_ = false;
      if (geometry) fail(path, line, "a '" + std::string(tok[0]) + "' inside a cstype ... end block (assimp 5.2.5 skips the whole block)");
      return 0;
    }
    if (st[0] == ' ' || st[0] == '\t') {
      if (geometry) fail(path, line, "an indented '" + std::string(tok[0]) + "' (assimp 5.2.5 skips it): remove the leading white space");
      return 0;
    }
    switch (st[0]) {
      case 'v':
        return st.size() > 1 && (st[1] == ' ' || st[1] == '\t') ? 'v' : 0;
      case 'f':
      case 'l':
      case 'p':
        if (tok[0].size() != 1)
          fail(path, line, "'" + std::string(tok[0]) + "' starts with '" + st[0] + "': assimp 5.2.5 reads it as a " +
                               (st[0] == 'f' ? "face" : st[0] == 'l' ? "line" : "point"));
        return st[0];
      case 'c':
        in_cstype_ = tok[0] == "cstype";
        return 0;
      default:
        return 0;
    }
  }

 private:
  bool in_cstype_ = false;
};

// The vertex statements: 3, 4 or 6 numbers, each one assimp counts as a
// number, finite, w not 0; texture coordinates of 2 or 3 numbers.
void check_vertex(const std::string& path, int line, int64_t vertex, const std::vector<std::string_view>& tok) {
  const size_t n = tok.size() - 1;
  if (n != 3 && n != 4 && n != 6)
    fail(path, line, "a vertex of " + std::to_string(n) + " numbers (assimp 5.2.5 reads x y z, x y z w or x y z r g b)");
  for (size_t k = 1; k <= n; ++k) {
    if (k <= 3) check_finite(path, line, vertex, tok[k]);
    if (!assimp_number(tok[k]))
      fail(path, line, "'" + std::string(tok[k]) + "' is not a number assimp 5.2.5 reads (it would drop the vertex)" +
                           (tok[k][0] == '.' ? ": write 0" + std::string(tok[k]) : std::string()));
    check_assimp_real(path, line, tok[k]);
  }
  double w = 1;
  if (n == 4 && parse_real(tok[4], w) && w == 0) fail(path, line, "a vertex with w = 0 (x/w is not a point)");
}

}  // namespace

PrecheckResult precheck_obj(const std::string& path, const std::string& text, std::vector<std::string>& warnings) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0)
    fail(path, 1, "the file starts with a UTF-8 byte-order mark (assimp 5.2.5 would lose its first statement)");
  if (const int line = odd_line_end(text)) fail(path, line, kOddLineEnd);

  std::vector<std::string_view> tok;
  std::string st;
  int64_t total = 0;  // first pass: positive indices may point forward
  AssimpView view1;
  for (ObjStatements s(path, text); s.next(st);) {
    split_tokens(st, tok);
    const char kind = view1.kind(path, s.line(), st, tok);
    // assimp counts a vertex's numbers to the end of the line, a comment's included.
    if ((kind == 'v' || (!tok.empty() && (tok[0] == "vt" || tok[0] == "vn"))) && st.find('#') != std::string::npos)
      fail(path, s.line(), "a comment after '" + std::string(tok[0]) + "' (assimp 5.2.5 counts its numbers too): put it "
                           "on a line of its own");
    if (kind == 'v') check_vertex(path, s.line(), ++total, tok);
    if (!tok.empty() && tok[0] == "vt" && tok.size() == 2) fail(path, s.line(), "a one-number 'vt' (assimp 5.2.5 refuses it)");
  }

  ObjMaterials materials(path, warnings);
  AssimpView view2;
  int64_t seen = 0;
  uint64_t polygons = 0;
  for (ObjStatements s(path, text); s.next(st);) {
    const int no = s.line();
    split_tokens(st, tok);
    const char kind = view2.kind(path, no, st, tok);
    if (kind == 'v') ++seen;
    if (kind != 0 || tok.empty()) {
    } else if (tok[0] == "mtllib" && tok.size() >= 2) {
      materials.libraries(no, rest_of(st, "mtllib"));
    } else if (tok[0] == "usemtl" && tok.size() >= 2) {
      materials.use(no, rest_of(st, "usemtl"));
    }
    if (kind != 'f' && kind != 'l' && kind != 'p') continue;
    const std::string what = kind == 'f' ? "face" : kind == 'l' ? "line" : "point";
    if (st.find('#') != std::string::npos)
      fail(path, no, "a comment after a " + what + " (assimp 5.2.5 refuses it): put it on a line of its own");
    if (tok.size() == 1) continue;  // empty: assimp warns and reads the rest
    if (kind == 'f') {
      if (tok.size() < 4) fail(path, no, "a face of " + std::to_string(tok.size() - 1) + " corners (a polygon needs 3)");
      ++polygons;
    }
    for (size_t k = 1; k < tok.size(); ++k) {
      const std::string_view corner = tok[k];
      if (std::count(corner.begin(), corner.end(), '/') > 2)
        fail(path, no, "corner '" + std::string(corner) + "' has more than v/vt/vn (assimp 5.2.5 drops the rest of the " + what + ")");
      for (size_t at = 0; at <= corner.size();) {
        const size_t slash = std::min(corner.find('/', at), corner.size());
        if (!index_part_ok(corner.substr(at, slash - at)))
          fail(path, no, "corner '" + std::string(corner) + "': an index assimp 5.2.5 misreads (write a plain non-zero "
                             "integer: no leading '0' or '+', at most 2147483647)");
        at = slash + 1;
      }
      int64_t i = 0;
      if (!parse_leading_integer(corner, i)) fail(path, no, "corner '" + std::string(corner) + "' has no vertex index");
      if (i > total || (i < 0 && seen + i < 0))
        fail(path, no,
             "vertex index " + std::to_string(i) + " is out of range (" +
                 (i > 0 ? "the file has " + vertices_text(total) : vertices_text(seen) + " so far") + ")");
    }
  }
  return {polygons, materials.undefined()};
}

}  // namespace girtd
