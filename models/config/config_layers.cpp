#include "config/config_layers.hpp"

#include <functional>
#include <optional>

#include "common/file_text.hpp"
#include "common/json_text.hpp"
#include "girtd/default_config.hpp"

namespace girtd {

using nlohmann::json;

ConfigLayers ConfigLayers::builtin() {
  ConfigLayers c;
  const std::string text = kDefaultConfigJson;
  c.merged_ = json::parse(text);
  for (const auto& [key, line] : json_key_lines(text)) c.places_[key] = {kDefaultConfigPath, line, 0};
  // A key the built-in configuration leaves null takes a number or null.
  std::function<void(const json&, const std::string&)> find_nullable = [&](const json& j, const std::string& path) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string key = path.empty() ? it.key() : path + "." + it.key();
      if (it->is_object()) find_nullable(*it, key);
      if (it->is_null()) c.nullable_.insert(key);
    }
  };
  find_nullable(c.merged_, "");
  c.add_constants();
  return c;
}

// config/constants.json's leaves ({"value", "why"}) join the tree at their
// paths, so the merged configuration (report.json's `config`) has them like
// any key; merge() refuses another value for one of them.
void ConfigLayers::add_constants() {
  const std::string text = kDesignConstantsJson;
  const std::map<std::string, int> lines = json_key_lines(text);
  std::function<void(const json&, json&, const std::string&)> walk = [&](const json& j, json& into,
                                                                          const std::string& path) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string key = path.empty() ? it.key() : path + "." + it.key();
      if (it->contains("value")) {
        into[it.key()] = it->at("value");
        constants_[key] = {it->at("value"), it->at("why").get<std::string>()};
        const auto line = lines.find(key);
        places_[key] = {kDesignConstantsPath, line == lines.end() ? 0 : line->second, 0};
      } else {
        walk(*it, into[it.key()], key);
      }
    }
  };
  walk(json::parse(text), merged_, "");
}

void ConfigLayers::merge_file(const std::string& path) {
  const std::optional<std::string> text = read_file_text(path);
  if (!text) throw InputError(path, 0, "cannot open configuration file");
  const json patch = parse_json_text(*text, path);
  if (!patch.is_object()) throw InputError(path, 1, "a configuration must be a JSON object");
  ++layers_;
  merge(merged_, patch, "", path, json_key_lines(*text));
  files_.push_back(path);
}

void ConfigLayers::merge_json(const json& patch, const std::string& origin) {
  if (!patch.is_object()) throw InputError(origin, 0, "a configuration must be a JSON object");
  ++layers_;
  merge(merged_, patch, "", origin, {});
}

// Refuses keys `base` does not have and values of another JSON type: a typo
// in a config must not be silently ignored.
void ConfigLayers::merge(json& base, const json& patch, const std::string& path, const std::string& origin,
                         const std::map<std::string, int>& lines) {
  for (auto it = patch.begin(); it != patch.end(); ++it) {
    const std::string key = path.empty() ? it.key() : path + "." + it.key();
    const auto line = lines.find(key);
    const int at = line == lines.end() ? 0 : line->second;
    if (!base.contains(it.key())) throw InputError(origin, at, key + ": unknown configuration key");
    json& target = base[it.key()];
    if (const auto constant = constants_.find(key); constant != constants_.end()) {
      if (*it != constant->second.value)
        throw InputError(origin, at, key + ": fixed by the design at " + constant->second.value.dump() + " (" +
                                         constant->second.why + "): not a setting");
      continue;
    }
    if (target.is_object()) {
      if (!it->is_object()) throw InputError(origin, at, key + ": must be an object");
      merge(target, *it, key, origin, lines);
      continue;
    }
    // A real may replace a real; an integer field takes integers only.
    const bool both_numbers =
        target.is_number() && it->is_number() && (!target.is_number_integer() || it->is_number_integer());
    const bool nullable = nullable_.count(key) && (it->is_null() || it->is_number());
    if (!both_numbers && !nullable && target.type() != it->type())
      throw InputError(origin, at, key + ": has the wrong type (expected " +
                                       (nullable_.count(key) ? std::string("a number or null")
                                                             : std::string(target.type_name())) + ")");
    target = *it;
    places_[key] = {origin, at, layers_};
  }
}

std::string ConfigLayers::last_set(const std::vector<std::string>& keys) const {
  std::string best = keys.front();
  auto rank = [&](const std::string& k) {
    const auto it = places_.find(k);
    return it == places_.end() ? std::pair<int, int>{-1, 0} : std::pair<int, int>{it->second.layer, it->second.line};
  };
  for (const std::string& k : keys)
    if (rank(k) > rank(best)) best = k;
  return best;
}

InputError ConfigLayers::error(const std::string& key, const std::string& what) const {
  const auto it = places_.find(key);
  if (it == places_.end()) return InputError(kDefaultConfigPath, 0, key + ": " + what);
  return InputError(it->second.file, it->second.line, key + ": " + what);
}

}  // namespace girtd
