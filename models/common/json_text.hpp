// JSON text a user wrote (a scene, a --config file) parsed into nlohmann's
// json: every parser error is an InputError "FILE:LINE: invalid JSON: ...".
#pragma once

#include <algorithm>
#include <cctype>
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
