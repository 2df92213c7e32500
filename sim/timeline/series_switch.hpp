// report.html's series — the stage timelines, the heat maps, the FIFOs'
// occupancy — are recorded on every timed run unless the environment sets
// GIRTD_NO_SERIES: `girtd bench --speed` renders with and without it to
// measure what they cost (the page then shows its tables only).
#pragma once

#include <cstdlib>

namespace girtd {

inline bool record_series() {
  static const bool on = std::getenv("GIRTD_NO_SERIES") == nullptr;
  return on;
}

}  // namespace girtd
