#include "accuracy/config_variants.hpp"

#include "common/input_error.hpp"

namespace girtd {

namespace {

nlohmann::json parse_value(const std::string& text) {
  const nlohmann::json v = nlohmann::json::parse(text, nullptr, false);
  return v.is_discarded() || v.is_object() || v.is_array() ? nlohmann::json(text) : v;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  size_t at = 0;
  for (size_t next; (next = s.find(sep, at)) != std::string::npos; at = next + 1) out.push_back(s.substr(at, next - at));
  out.push_back(s.substr(at));
  return out;
}

}  // namespace

nlohmann::json ConfigVariant::override_json() const {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, value] : settings.items()) {
    nlohmann::json* node = &out;
    const std::vector<std::string> parts = split(key, '.');
    for (size_t i = 0; i + 1 < parts.size(); ++i) node = &(*node)[parts[i]];
    (*node)[parts.back()] = value;
  }
  return out;
}

std::vector<ConfigVariant> config_variants(const std::vector<std::string>& specs) {
  std::vector<ConfigVariant> out = {{"base", nlohmann::json::object()}};
  for (const std::string& spec : specs) {
    const size_t eq = spec.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
      throw InputError("--vary", 0, "expected KEY=V1,V2,..., got '" + spec + "'");
    const std::string key = spec.substr(0, eq);
    std::vector<ConfigVariant> next;
    for (const ConfigVariant& v : out)
      for (const std::string& text : split(spec.substr(eq + 1), ',')) {
        if (text.empty()) throw InputError("--vary", 0, "'" + spec + "': an empty value");
        ConfigVariant w = v;
        w.settings[key] = parse_value(text);
        w.label = (v.label == "base" ? "" : v.label + ",") + key + "=" + text;
        next.push_back(w);
      }
    out = next;
  }
  return out;
}

}  // namespace girtd
