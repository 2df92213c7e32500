// One CSV cell from a JSON value (the accuracy and sweep tables): null is
// empty, text as it is, anything else as JSON; quoted, quotes doubled
// (RFC 4180), when it holds a comma, a quote or a line break.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace girtd {

inline std::string csv_field(const nlohmann::json& v) {
  const std::string t = v.is_null() ? std::string() : v.is_string() ? v.get<std::string>() : v.dump();
  if (t.find_first_of(",\"\n") == std::string::npos) return t;
  std::string q;
  for (char c : t) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return "\"" + q + "\"";
}

}  // namespace girtd
