// In-memory form of a trace file (traces/FORMAT.md): frames of primitives at
// one pipeline level.
#pragma once

#include <string>
#include <vector>

#include "common/types.hpp"
#include "dda/dda_params.hpp"

namespace girtd {

enum class TraceLevel { kTriangle, kDda };

const char* level_name(TraceLevel level);
// Throws InputError(origin, line, ...) for an unknown name.
TraceLevel parse_level(const std::string& name, const std::string& origin, int line);

struct TraceFrame {
  FrameSettings settings;
  std::vector<Triangle> triangles;  // level triangle
  std::vector<DdaParams> dda;       // level dda
  size_t primitive_count() const { return triangles.size() + dda.size(); }
};

struct Trace {
  std::string path;
  TraceLevel level = TraceLevel::kTriangle;
  std::vector<TraceFrame> frames;
  size_t primitive_count() const;
};

}  // namespace girtd
