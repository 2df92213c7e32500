// `--vary KEY=V1,V2,...` (repeatable): every combination of the values, each
// a configuration override merged over the run's --config files.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace girtd {

struct ConfigVariant {
  std::string label;        // "base", or "key=value,key=value" in --vary order
  nlohmann::json settings;  // {"dotted.key": value, ...}
  nlohmann::json override_json() const;  // nested, as a --config file holds it
};

// A value is read as JSON (numbers, true, false, null), else as text.
// Throws InputError("--vary", ...) on a malformed spec.
std::vector<ConfigVariant> config_variants(const std::vector<std::string>& specs);

}  // namespace girtd
