// Line numbers for a JSON document, by JSON pointer ("/models/0/file"), so
// errors about a scene's content can say FILE:LINE (nlohmann::json keeps no
// positions), and the nesting limit checked before anything parses it.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace girtd {

// Deeper nesting of [ and { is refused: no scene needs it, and recursive
// code (parsing, dumping, freeing a json value) must never meet it.
inline constexpr int kMaxJsonDepth = 64;

// InputError "path:LINE: ..." at the first [ or { beyond kMaxJsonDepth. Works
// on any text (valid JSON or not): run it before parsing.
void check_json_nesting(const std::string& text, const std::string& path);

class JsonLines {
 public:
  // `text`: a document nlohmann::json has accepted. One pass, no recursion,
  // memory linear in the number of values (each stores its own key or index,
  // not its path).
  explicit JsonLines(const std::string& text);
  // The line of the value (or its key) at `pointer` (RFC 6901: ~0 = ~,
  // ~1 = /), else of its nearest ancestor that exists.
  int line(const std::string& pointer) const;

 private:
  std::vector<int> line_of_;                                   // per value, in document order; 0 = the root
  std::unordered_map<size_t, std::vector<size_t>> items_;      // array -> its elements
  std::map<std::pair<size_t, std::string>, size_t> members_;  // (object, key) -> member
};

}  // namespace girtd
