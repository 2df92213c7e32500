// Scratch input files and the InputError text they give, for the tests of
// scene and model input.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "io/model_import.hpp"

namespace girtd::test {

inline const std::string kModels = std::string(GIRTD_SOURCE_DIR) + "/traces/models/";

// Writes `text` to /tmp/girtd_frontend_test_NAME and returns the path.
inline std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = "/tmp/girtd_frontend_test_" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The InputError's "FILE:LINE: what", or "" when nothing was thrown.
template <typename F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.formatted();
  }
  return "";
}

}  // namespace girtd::test
