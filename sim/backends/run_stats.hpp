// What a render measured, back-end independent; std::nullopt = not measured.
// The report's keys and which back ends know them: report/report_keys.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "backends/sampled_timing.hpp"
#include "backends/screen_maps.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"
#include "frontend/frontend_counts.hpp"
#include "had/had.hpp"

namespace girtd {

struct StageStats {
  std::string name;
  uint64_t items = 0;
  std::optional<double> busy_s, stall_s;
  // Timed back ends: stall_s = starved_s + blocked_s.
  std::optional<double> starved_s;    // waiting for input
  std::optional<double> blocked_s;    // waiting for room downstream
  std::optional<double> flops;        // arithmetic done (front-end stages, preparer)
  std::optional<uint64_t> fifo_in_max;  // most items ever in the FIFO in front of it
  // Timed front-end stages: when each frame began and ended (modeled s).
  std::vector<double> frame_begin_s, frame_end_s;
  // Timed back ends, for the report page's timelines: the SystemC stages'
  // starved, busy and blocked seconds per bin of `series_bin_s`, and the
  // FIFO in front's largest occupancy per bin of `fifo_in_bin_s`
  // (sim/timeline/time_series.hpp). Empty where not sampled.
  double series_bin_s = 0;
  std::vector<std::array<double, 3>> series;
  double fifo_in_bin_s = 0;
  std::vector<double> fifo_in_series;
};

// A stage of an untimed back end: items only.
inline StageStats untimed_stage(const std::string& name, uint64_t items) {
  StageStats s;
  s.name = name;
  s.items = items;
  return s;
}

// Whole-pipeline timing (the approx and rtl back ends).
struct PipelineTiming {
  double modeled_s = 0;
  // Frames 2..N: their pixels over the time from frame 1's swap to frame
  // N's (the thesis' rate is sustained, the pipeline full); none for one frame.
  std::optional<double> sustained_pixels_per_s;
  std::string bottleneck;           // the stage with the most busy time
  uint64_t cache_accesses = 0, page_misses = 0;
  double dda_busy_s = 0;            // DDA clocks on triangles
  double dda_fifo_full_s = 0;       // DDA waiting on a full DDA -> HAD FIFO
  double dda_starved_s = 0;         // DDA idle, no parameter set (the front end starving it)
  double had_page_wait_s = 0;       // HAD waiting on page write-backs and fetches
  double frame_clear_swap_s = 0;    // clearing frames; writing the cache back and swapping at their ends
  uint64_t preparer_triangles = 0;  // parameter sets the preparer delivered
  double preparer_capacity_triangles_per_s = 0;  // its rate over its flops per triangle
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
  std::optional<PipelineTiming> timing;
  std::optional<SamplingStats> sampling;  // approx with sampled timing (render --sample-timing)
  std::optional<ScreenMaps> maps;         // the timed back ends (report.html's heat maps)
  double wall_s = 0;
};

}  // namespace girtd
