// Tokens and numbers of text model files (OBJ, OFF, ASCII PLY), for the
// pre-checks in model_precheck.cpp and ply_precheck.cpp.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace girtd {

// The whitespace-separated tokens of `line`, up to a '#' comment.
inline void split_tokens(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == '\v' || line[i] == '\f'))
      ++i;
    if (i >= line.size() || line[i] == '#') return;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '\v' &&
           line[i] != '\f' && line[i] != '#')
      ++i;
    out.push_back(line.substr(start, i - start));
  }
}

// A decimal integer (optional sign) making up the whole of `t`, |value| < 10^18.
inline bool parse_integer(std::string_view t, int64_t& value) {
  size_t i = t.size() > 0 && (t[0] == '-' || t[0] == '+') ? 1 : 0;
  if (i == t.size() || t.size() - i > 18) return false;
  int64_t v = 0;
  for (size_t k = i; k < t.size(); ++k) {
    if (t[k] < '0' || t[k] > '9') return false;
    v = v * 10 + (t[k] - '0');
  }
  value = t[0] == '-' ? -v : v;
  return true;
}

// The leading integer of an OBJ face corner "V", "V/T", "V//N" or "V/T/N".
inline bool parse_leading_integer(std::string_view t, int64_t& value) {
  return parse_integer(t.substr(0, t.find('/')), value);
}

// A real number making up the whole of `t` (strtod's syntax, so "nan" and
// "1e999" parse: to NaN and infinity).
inline bool parse_real(std::string_view t, double& value) {
  if (t.empty() || t.size() > 64) return false;
  const std::string s(t);
  char* end = nullptr;
  errno = 0;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

}  // namespace girtd
