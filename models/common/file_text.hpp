// A whole file as bytes: the one way the readers of whole files (configs,
// scenes, the RTL generator, variant stamps) load them.
#pragma once

#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace girtd {

// The file's bytes, or nothing when it cannot be opened.
inline std::optional<std::string> read_file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace girtd
