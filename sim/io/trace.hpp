// In-memory form of a trace file (traces/FORMAT.md): frames of primitives at
// one pipeline level.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/types.hpp"
#include "config/params.hpp"
#include "dda/dda_params.hpp"
#include "frontend/world_frame.hpp"

namespace girtd {

// kThesis: the thesis appendix program's own units (models/thesis/README.md).
enum class TraceLevel { kTriangle, kDda, kPolygon, kThesis };

// A polygon trace's `lights` record holds at most this many directional lights.
inline constexpr int64_t kMaxTraceLights = 64;
// A trace file's bounds (an endless stream stops at them): a line (a vpoly
// of 65,536 corners at 17 digits a number is about 10 MiB), the whole file
// (2 GiB: some 20 million triangles).
inline constexpr uint64_t kMaxTraceLineBytes = uint64_t(64) << 20;
inline constexpr uint64_t kMaxTraceBytes = uint64_t(2) << 30;

const char* level_name(TraceLevel level);
// Throws InputError(origin, line, ...) for an unknown name.
TraceLevel parse_level(const std::string& name, const std::string& origin, int line);

struct TraceFrame {
  FrameSettings settings;
  std::vector<Triangle> triangles;  // level triangle (level thesis: vertices in the program's units)
  std::vector<DdaParams> dda;       // level dda
  WorldFrame world;                 // level polygon: polygons, surfaces, lights, camera
  size_t primitive_count() const { return triangles.size() + dda.size() + world.polygons.size(); }
};

struct Trace {
  std::string path;
  TraceLevel level = TraceLevel::kTriangle;
  std::vector<TraceFrame> frames;
  // What the reader could go on from ("FILE: what"): each is printed as
  // "warning: ..." and listed in report.json's "warnings".
  std::vector<std::string> warnings;
  size_t primitive_count() const;
};

// Config dda.q_override (render --aa): every frame's Q, and every DDA
// parameter set's, replaced as the input is read (not the thesis level).
void apply_q_override(Trace& trace, const Params& params);
void apply_q_override(FrameSettings& settings, const Params& params);

}  // namespace girtd
