// --config: the built-in configuration, or a user file merged over it.
#pragma once

#include <string>

#include "config/params.hpp"

namespace girtd {

inline Params load_params(const std::string& config_path) {
  return config_path.empty() ? Params::defaults() : Params::from_file(config_path);
}

}  // namespace girtd
