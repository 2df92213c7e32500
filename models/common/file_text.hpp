// A whole file as bytes: the one way the readers of whole files (configs,
// scenes, sweep specs, the RTL generator, variant stamps) load them. Bounded:
// a path may name an endless stream (/dev/zero, a FIFO).
#pragma once

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>

#include "common/input_error.hpp"

namespace girtd {

// The largest whole file read (a scene with inline meshes is the largest).
inline constexpr uint64_t kMaxWholeFileBytes = uint64_t(256) << 20;  // 256 MiB

// The file's bytes, or nothing when it cannot be opened. Past
// kMaxWholeFileBytes: InputError(path, 0, ...), read no further.
inline std::optional<std::string> read_file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<size_t>(in.gcount()));
    if (text.size() > kMaxWholeFileBytes)
      throw InputError(path, 0, "larger than " + std::to_string(kMaxWholeFileBytes >> 20) +
                                    " MiB, the limit of a scene, configuration or sweep file (or an endless stream)");
  }
  return text;
}

}  // namespace girtd
