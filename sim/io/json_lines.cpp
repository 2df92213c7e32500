#include "io/json_lines.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "io/number_text.hpp"

namespace girtd {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// The string whose opening quote is at text[pos], decoded; pos moves past
// its closing quote. (JSON strings hold no raw newline: lines stay counted.)
std::string string_at(const std::string& text, size_t& pos) {
  const size_t start = pos++;
  bool escapes = false;
  while (pos < text.size() && text[pos] != '"') {
    if (text[pos] == '\\') {
      escapes = true;
      ++pos;
    }
    ++pos;
  }
  pos = std::min(pos + 1, text.size());
  if (!escapes) return text.substr(start + 1, pos - start - 2);
  return nlohmann::json::parse(text.begin() + static_cast<long>(start), text.begin() + static_cast<long>(pos))
      .get<std::string>();
}

// One reference token of a JSON pointer, ~1 -> / and ~0 -> ~.
std::string unescape_token(const std::string& t) {
  std::string out;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '~' && i + 1 < t.size() && (t[i + 1] == '0' || t[i + 1] == '1')) {
      out += t[i + 1] == '0' ? '~' : '/';
      ++i;
    } else {
      out += t[i];
    }
  }
  return out;
}

}  // namespace

void check_json_nesting(const std::string& text, const std::string& path) {
  int depth = 0, line = 1;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw InputError(path, line, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    } else if (c == ']' || c == '}') {
      depth = std::max(0, depth - 1);
    }
  }
}

JsonLines::JsonLines(const std::string& text) {
  struct Open {
    size_t node;
    bool object;
  };
  std::vector<Open> open;  // the arrays and objects the scan is inside
  std::string key;
  int key_line = 0, line = 1;
  bool have_key = false;
  for (size_t pos = 0; pos < text.size();) {
    const char c = text[pos];
    if (c == '\n') ++line;
    if (is_space(c) || c == ',' || c == ':') {
      ++pos;
      continue;
    }
    if (c == '}' || c == ']') {
      if (!open.empty()) open.pop_back();
      ++pos;
      continue;
    }
    if (!open.empty() && open.back().object && !have_key) {  // a member's key
      key = string_at(text, pos);
      key_line = line;
      have_key = true;
      continue;
    }
    // A value starts here; an object member is found at its key's line.
    const size_t node = line_of_.size();
    if (open.empty()) {
      if (!line_of_.empty()) break;  // only one root value
      line_of_.push_back(line);
    } else if (open.back().object) {
      members_.emplace(std::make_pair(open.back().node, std::move(key)), node);
      line_of_.push_back(key_line);
      have_key = false;
    } else {
      items_[open.back().node].push_back(node);
      line_of_.push_back(line);
    }
    if (c == '{' || c == '[') {
      open.push_back({node, c == '{'});
      ++pos;
    } else if (c == '"') {
      string_at(text, pos);
    } else {
      while (pos < text.size() && !is_space(text[pos]) && text[pos] != ',' && text[pos] != '}' && text[pos] != ']')
        ++pos;
    }
  }
  if (line_of_.empty()) line_of_.push_back(1);
}

int JsonLines::line(const std::string& pointer) const {
  size_t node = 0;
  for (size_t at = 0; at < pointer.size() && pointer[at] == '/';) {
    size_t end = pointer.find('/', at + 1);
    if (end == std::string::npos) end = pointer.size();
    const std::string token = unescape_token(pointer.substr(at + 1, end - at - 1));
    at = end;
    auto m = members_.find({node, token});
    if (m != members_.end()) {
      node = m->second;
      continue;
    }
    auto a = items_.find(node);
    int64_t index = -1;  // an array index is digits only
    const bool digits = std::all_of(token.begin(), token.end(), [](unsigned char ch) { return ch >= '0' && ch <= '9'; });
    if (a == items_.end() || !digits || read_integer(token, index) != NumberRead::kOk ||
        uint64_t(index) >= a->second.size())
      break;
    node = a->second[size_t(index)];
  }
  return line_of_[node];
}

}  // namespace girtd
