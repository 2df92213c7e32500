#include "frontend/json_lines.hpp"

namespace girtd {

JsonLines::JsonLines(const std::string& text) : text_(text) { value(""); }

int JsonLines::line(std::string pointer) const {
  for (;;) {
    auto it = lines_.find(pointer);
    if (it != lines_.end()) return it->second;
    const size_t slash = pointer.rfind('/');
    if (slash == std::string::npos) return 1;
    pointer.erase(slash);
  }
}

void JsonLines::skip_ws() {
  while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r')) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
}

// A string's content with escapes reduced to the escaped character (enough
// for keys), encoded for a JSON pointer (~ -> ~0, / -> ~1).
std::string JsonLines::string_token() {
  std::string out;
  ++pos_;  // opening quote
  while (pos_ < text_.size() && text_[pos_] != '"') {
    if (text_[pos_] == '\\') ++pos_;
    const char c = pos_ < text_.size() ? text_[pos_] : '"';
    out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    ++pos_;
  }
  ++pos_;  // closing quote
  return out;
}

void JsonLines::value(const std::string& path) {
  skip_ws();
  lines_.emplace(path, line_);
  if (pos_ >= text_.size()) return;
  const char c = text_[pos_];
  if (c == '{' || c == '[') {
    ++pos_;
    for (int index = 0;; ++index) {
      skip_ws();
      if (pos_ >= text_.size()) return;
      if (text_[pos_] == '}' || text_[pos_] == ']') {
        ++pos_;
        return;
      }
      if (text_[pos_] == ',') {
        ++pos_;
        skip_ws();
      }
      std::string child = path + "/";
      if (c == '{') {
        child += string_token();
        lines_.emplace(child, line_);
        skip_ws();
        ++pos_;  // ':'
      } else {
        child += std::to_string(index);
      }
      value(child);
    }
  }
  if (c == '"') {
    string_token();
    return;
  }
  while (pos_ < text_.size() && text_[pos_] != ',' && text_[pos_] != '}' && text_[pos_] != ']' && text_[pos_] != '\n')
    ++pos_;
}

}  // namespace girtd
