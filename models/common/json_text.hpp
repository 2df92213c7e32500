// JSON text a user wrote (a scene, a --config file) parsed into nlohmann's
// json: every parser error is an InputError "FILE:LINE: invalid JSON: ...".
#pragma once

#include <algorithm>
#include <cctype>
#include <map>
#include <vector>
#include <string>

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"

namespace girtd {

namespace json_text_detail {

inline int line_at(const std::string& text, size_t byte) {
  const size_t upto = std::min(byte, text.size());
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(upto), '\n'));
}

}  // namespace json_text_detail

// The line of every object key in valid JSON text, by dotted path
// ("ep.color.frac_bits"; keys inside arrays are not listed). nlohmann's
// parser keeps no positions, so the text is walked once more.
inline std::map<std::string, int> json_key_lines(const std::string& text) {
  struct Open {
    char bracket;     // '{' or '['
    std::string key;  // an object's key being read
  };
  std::map<std::string, int> lines;
  std::vector<Open> open;
  std::string last_string;
  int line = 1, last_string_line = 1;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
    } else if (c == '"') {
      last_string.clear();
      last_string_line = line;
      for (++i; i < text.size() && text[i] != '"'; ++i) last_string += text[i] == '\\' ? text[++i] : text[i];
    } else if (c == ':' && !open.empty()) {
      open.back().key = last_string;
      std::string dotted;
      bool in_array = false;
      for (const Open& o : open) {
        in_array = in_array || o.bracket == '[';
        dotted += (dotted.empty() ? "" : ".") + o.key;
      }
      if (!in_array) lines[dotted] = last_string_line;
    } else if (c == '{' || c == '[') {
      open.push_back({c, ""});
    } else if ((c == '}' || c == ']') && !open.empty()) {
      open.pop_back();
    }
  }
  return lines;
}

inline nlohmann::json parse_json_text(const std::string& text, const std::string& path) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    std::string what = e.what();
    const size_t at = what.find("syntax error");
    throw InputError(path, json_text_detail::line_at(text, e.byte > 0 ? e.byte - 1 : 0),
                     "invalid JSON: " + (at == std::string::npos ? what : what.substr(at)));
  } catch (const nlohmann::json::exception& e) {
    // out_of_range 406, "number overflow parsing '1e999'": no byte offset,
    // so the line is where the number's text first stands as a value (after
    // ':', ',' or '[', not inside a string).
    std::string what = e.what();
    const size_t q = what.find('\'');
    int line = 0;
    if (q != std::string::npos && what.back() == '\'') {
      const std::string number = what.substr(q + 1, what.size() - q - 2);
      for (size_t at = text.find(number); at != std::string::npos && line == 0; at = text.find(number, at + 1)) {
        size_t before = at;
        while (before > 0 && std::isspace(static_cast<unsigned char>(text[before - 1]))) --before;
        if (before > 0 && (text[before - 1] == ':' || text[before - 1] == ',' || text[before - 1] == '['))
          line = json_text_detail::line_at(text, at);
      }
    }
    const size_t at = what.find("] ");
    throw InputError(path, line, "invalid JSON: " + (at == std::string::npos ? what : what.substr(at + 2)));
  }
}

}  // namespace girtd
