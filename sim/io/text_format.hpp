// printf into a std::string, for the cells of the tables and the lines of
// the reports that the commands write. Every argument is a number and is
// passed as a double (so the formats are %f, %g or %e, whatever the
// argument's type).
#pragma once

#include <cstdio>
#include <string>

namespace girtd {

template <typename... Numbers>
std::string format_numbers(const char* format, Numbers... numbers) {
  const int n = std::snprintf(nullptr, 0, format, static_cast<double>(numbers)...);
  if (n <= 0) return "";
  std::string s(static_cast<size_t>(n), '\0');
  std::snprintf(s.data(), s.size() + 1, format, static_cast<double>(numbers)...);
  return s;
}

}  // namespace girtd
