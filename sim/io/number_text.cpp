#include "io/number_text.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace girtd {
namespace {

// from_chars takes no '+': skip one before a digit or a point.
std::string_view without_plus(std::string_view t) {
  if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  return t;
}

// from_chars says "out of range" both past double's largest value and
// below its smallest: tell them apart by the decimal position of the first
// significant digit plus the exponent (an exponent past int64 by its sign).
double out_of_range_value(std::string_view t) {
  const bool negative = !t.empty() && t[0] == '-';
  const std::string_view body = t.substr(negative || (!t.empty() && t[0] == '+') ? 1 : 0);
  const size_t e = body.find_first_of("eE");
  const std::string_view digits = body.substr(0, e);
  const size_t point = digits.find('.');
  const std::string_view whole = digits.substr(0, point);
  const std::string_view fraction = point == std::string_view::npos ? std::string_view() : digits.substr(point + 1);
  // 123.4 -> 3, 0.05 -> -1: the first significant digit is at 10^(magnitude - 1).
  int64_t magnitude = 0;
  if (const size_t first = whole.find_first_not_of('0'); first != std::string_view::npos)
    magnitude = int64_t(whole.size() - first);
  else if (const size_t zeros = fraction.find_first_not_of('0'); zeros != std::string_view::npos)
    magnitude = -int64_t(zeros);
  int64_t exponent = 0;
  if (e != std::string_view::npos) {
    const std::string_view text = body.substr(e + 1);
    if (read_integer(text, exponent) != NumberRead::kOk)
      exponent = !text.empty() && text[0] == '-' ? -(int64_t{1} << 62) : (int64_t{1} << 62);
  }
  const bool huge = magnitude + exponent > 0;
  return std::copysign(huge ? HUGE_VAL : 0.0, negative ? -1.0 : 1.0);
}

}  // namespace

NumberRead read_integer(std::string_view text, int64_t& value) {
  const std::string_view t = without_plus(text);
  int64_t v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || end != t.data() + t.size() || ec == std::errc::invalid_argument) return NumberRead::kNotANumber;
  if (ec == std::errc::result_out_of_range) return NumberRead::kOutOfRange;
  value = v;
  return NumberRead::kOk;
}

NumberRead read_leading_real(std::string_view text, double& value, size_t& used) {
  const std::string_view t = without_plus(text);
  double v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec == std::errc::invalid_argument) return NumberRead::kNotANumber;
  used = size_t(end - t.data()) + (text.size() - t.size());
  if (ec == std::errc::result_out_of_range) {
    value = out_of_range_value(t.substr(0, size_t(end - t.data())));
    return NumberRead::kOutOfRange;
  }
  value = v;
  return NumberRead::kOk;
}

NumberRead read_real(std::string_view text, double& value) {
  size_t used = 0;
  const NumberRead r = read_leading_real(text, value, used);
  return r != NumberRead::kNotANumber && used == text.size() && !text.empty() ? r : NumberRead::kNotANumber;
}

}  // namespace girtd
