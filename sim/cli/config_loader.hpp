// --config FILE (repeatable): the built-in configuration with each file
// merged over it in order.
#pragma once

#include <string>
#include <vector>

#include "config/params.hpp"

namespace girtd {

using ConfigFiles = std::vector<std::string>;

inline Params load_params(const ConfigFiles& config_files) { return Params::from_files(config_files); }

// The same files as arguments for a child `girtd` run.
inline std::vector<std::string> config_args(const ConfigFiles& config_files) {
  std::vector<std::string> args;
  for (const std::string& f : config_files) args.insert(args.end(), {"--config", f});
  return args;
}

}  // namespace girtd
