// Line numbers for a JSON document, by JSON pointer ("/models/0/file"), so
// errors about a scene's content can say FILE:LINE (nlohmann::json keeps no
// positions). Scans text that nlohmann::json has already accepted.
#pragma once

#include <string>
#include <unordered_map>

namespace girtd {

class JsonLines {
 public:
  explicit JsonLines(const std::string& text);
  // The line of the value (or its key) at `pointer`, else of its nearest
  // ancestor; 1 for the root.
  int line(std::string pointer) const;

 private:
  void value(const std::string& path);
  void skip_ws();
  std::string string_token();

  const std::string& text_;
  size_t pos_ = 0;
  int line_ = 1;
  std::unordered_map<std::string, int> lines_;
};

}  // namespace girtd
