// What a render measured, back-end independent. std::nullopt = this back end
// does not model it (reported as null and listed in not_modeled).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"
#include "frontend/frontend_counts.hpp"
#include "had/had.hpp"

namespace girtd {

struct StageStats {
  std::string name;
  uint64_t items = 0;
  std::optional<double> busy_s, stall_s;
};

struct RunStats {
  uint64_t frames = 0;
  uint64_t triangles_in = 0;
  uint64_t triangles_drawn = 0;
  uint64_t pixels_generated = 0;
  HadCounts had;
  std::optional<PreparerCounts> preparer;
  std::optional<DdaRunStats> dda;  // summed over all triangles
  std::optional<FrontendCounts> frontend;  // when the input entered above the front end
  std::vector<StageStats> stages;
  double wall_s = 0;
};

}  // namespace girtd
