// Tokens, numbers and errors of model files, for the pre-checks
// (obj_precheck.cpp, model_precheck.cpp, ply_precheck.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/input_error.hpp"
#include "io/number_text.hpp"

namespace girtd {

[[noreturn]] inline void fail(const std::string& path, int line, const std::string& what) {
  throw InputError(path, line, what);
}

// A little-endian uint32 at `p` (binary STL and glTF containers).
inline uint32_t u32_at(const char* p) {
  uint32_t bits = 0;
  for (int i = 3; i >= 0; --i) bits = (bits << 8) | static_cast<unsigned char>(p[i]);
  return bits;
}

inline std::string vertices_text(int64_t n) { return std::to_string(n) + (n == 1 ? " vertex" : " vertices"); }

// The line (from 1) of the first line end in `text` that assimp 5.2.5 reads
// differently from this project's line splitting (its IsLineEnd also ends a
// line at a lone CR, a NUL and a form feed; its IsSpace does not take a
// vertical tab for a blank), or 0 when there is none.
inline int odd_line_end(std::string_view text) {
  int line = 1;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') ++line;
    else if (c == '\0' || c == '\f' || c == '\v' || (c == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')))
      return line;
  }
  return 0;
}

inline constexpr const char* kOddLineEnd =
    "a NUL, a form feed, a vertical tab or a CR without LF: assimp 5.2.5 reads lines and blanks there otherwise";

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

// A decimal integer (optional sign) making up the whole of `t`, of at most
// 18 digits (|value| < 10^18: counts and indices stay far from overflow).
inline bool parse_integer(std::string_view t, int64_t& value) {
  const size_t sign = !t.empty() && (t[0] == '-' || t[0] == '+') ? 1 : 0;
  return t.size() - sign <= 18 && read_integer(t, value) == NumberRead::kOk;
}

// The leading integer of an OBJ face corner "V", "V/T", "V//N" or "V/T/N".
inline bool parse_leading_integer(std::string_view t, int64_t& value) {
  return parse_integer(t.substr(0, t.find('/')), value);
}

// A real number making up the whole of `t` ("nan" and "1e999" parse: to
// NaN and infinity).
inline bool parse_real(std::string_view t, double& value) { return read_real(t, value) != NumberRead::kNotANumber; }

// Why assimp 5.2.5's fast_atof would read the real number `t` otherwise
// than its text says, or "" when it reads it right: only decimal syntax
// [+-]digits[.digits][(e|E)[+-]digits] (it stops at "0x", at a second '.'),
// digits after the point past the 15th only where dropping them (it does)
// leaves the float it reads as it is (an exporter's round-trip double such
// as 0.0009999999983333334 reads right), at most 18 digits
// before it (its overflow test misses some wraps), and within float's range.
inline std::string assimp_real_problem(std::string_view t) {
  size_t i = t.size() > 0 && (t[0] == '-' || t[0] == '+') ? 1 : 0;
  auto digits = [&]() {
    const size_t start = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i - start;
  };
  const size_t whole = digits();
  size_t fraction = 0, fraction_start = 0;
  if (i < t.size() && t[i] == '.') {
    ++i;
    fraction_start = i;
    fraction = digits();
  }
  if (whole + fraction == 0) return "is not a number";
  const size_t exponent_at = i;
  size_t exponent_digits = 0;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '-' || t[i] == '+')) ++i;
    exponent_digits = digits();
    if (exponent_digits == 0) return "is not a number";
  }
  if (i != t.size()) return "is not a decimal number";
  if (whole > 18) return "has more than 18 digits before the point";
  double d = 0;
  if (!parse_real(t, d) || !(std::fabs(d) <= 3.4028234663852886e38)) return "is out of a float's range";
  if (exponent_digits > 9) return "has an exponent of more than 9 digits";
  if (exponent_digits > 0) {
    // assimp scales the float it read by powf(10, e): 0e39 reads NaN,
    // 0.001e39 infinity, though both are in range.
    double mantissa = 0, exponent = 0;
    parse_real(t.substr(0, exponent_at), mantissa);
    parse_real(t.substr(exponent_at + 1), exponent);
    const float got = float(mantissa) * std::pow(10.0f, float(exponent)), want = float(d);
    if (!std::isfinite(got) || std::fabs(got - want) > 1e-5f * std::fabs(want) + 1.17549435e-38f)
      return "is read as " + (std::isnan(got) ? std::string("NaN") : std::isinf(got) ? "infinity" : std::to_string(got)) +
             " (assimp 5.2.5 applies the exponent as a float power of 10)";
  }
  if (fraction > 15) {
    const std::string kept = std::string(t.substr(0, fraction_start + 15)) + std::string(t.substr(fraction_start + fraction));
    double dropped = 0;
    parse_real(kept, dropped);
    const float want = float(d), got = float(dropped);
    if (want != got)
      return "has more than 15 digits after the point; assimp 5.2.5 drops the rest and would read " + kept;
  }
  return "";
}

// Refuses a real number assimp 5.2.5 would misread, naming it and its line.
inline void check_assimp_real(const std::string& path, int line, std::string_view t) {
  const std::string problem = assimp_real_problem(t);
  if (!problem.empty()) fail(path, line, "'" + std::string(t) + "' " + problem + " (assimp 5.2.5 would misread it)");
}

// A vertex coordinate that is a number must be finite.
inline void check_finite(const std::string& path, int line, int64_t vertex, std::string_view token) {
  double d = 0;
  if (parse_real(token, d) && !std::isfinite(d))
    fail(path, line, "vertex " + std::to_string(vertex) + " has a coordinate that is NaN or infinite");
}

}  // namespace girtd
