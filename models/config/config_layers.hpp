// The configuration as layers: the built-in config/girtd.json with the
// design's fixed constants (config/constants.json) in it, then each
// --config file merged over it in order (the later wins); a file that gives
// a constant another value is refused, with the constant's reason. Every leaf key
// remembers the file and line that set it last, so a value refused later
// (a range, a relation) is reported where the user wrote it:
// "FILE:LINE: key: what".
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"

namespace girtd {

class ConfigLayers {
 public:
  // config/girtd.json as built in, with config/constants.json in it.
  static ConfigLayers builtin();

  // Merges one user file; unknown keys and values of another JSON type are
  // refused at their line.
  void merge_file(const std::string& path);
  // Merges JSON that has no text (tests, sweep points): errors name `origin`.
  void merge_json(const nlohmann::json& patch, const std::string& origin);

  const nlohmann::json& merged() const { return merged_; }
  const std::vector<std::string>& files() const { return files_; }
  // The error for a value refused after merging, at the key's last setting.
  InputError error(const std::string& key, const std::string& what) const;
  // Of keys refused together (a relation), the one a user set last: the
  // later file, else the later line; a built-in value only if no user set any.
  std::string last_set(const std::vector<std::string>& keys) const;

 private:
  struct Place {
    std::string file;
    int line = 0;
    int layer = 0;  // 0: built in; 1, 2, ...: the user's files and patches in order
  };
  struct Constant {
    nlohmann::json value;
    std::string why;
  };
  void add_constants();
  void merge(nlohmann::json& base, const nlohmann::json& patch, const std::string& path, const std::string& origin,
             const std::map<std::string, int>& lines);
  nlohmann::json merged_;
  std::map<std::string, Place> places_;
  std::map<std::string, Constant> constants_;  // dotted key -> its value and reason
  std::set<std::string> nullable_;  // keys null in the built-in configuration: a number or null
  std::vector<std::string> files_;
  int layers_ = 0;
};

}  // namespace girtd
