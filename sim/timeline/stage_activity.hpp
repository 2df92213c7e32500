// What one pipeline stage did, in modeled seconds, and the occupancy of the
// FIFO in front of it. Plain C++ (no SystemC) so the report reads it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "timeline/series_switch.hpp"
#include "timeline/time_series.hpp"

namespace girtd {

// `t_s`: the modeled time of the push or pop (the report's occupancy
// timeline: the level held since the last one is noted in every bin it
// spans, so a bin without a push or pop still shows it).
struct FifoActivity {
  uint64_t pushed = 0, popped = 0;
  uint64_t max_occupancy = 0;
  FifoSeries occupancy{true};
  void push(double t_s) {
    if (record_) occupancy.note_max(0, last_s_, t_s, double(pushed - popped));
    ++pushed;
    if (pushed - popped > max_occupancy) max_occupancy = pushed - popped;
    if (record_) occupancy.note_max(0, t_s, t_s, double(pushed - popped));
    last_s_ = t_s;
  }
  void pop(double t_s) {
    if (record_) occupancy.note_max(0, last_s_, t_s, double(pushed - popped));
    ++popped;
    last_s_ = t_s;
  }

 private:
  double last_s_ = 0;
  bool record_ = record_series();
};

enum class StageState : uint8_t { kStarved, kBusy, kBlocked };

struct StageActivity {
  std::string name;
  StageState state = StageState::kStarved;  // now (waveforms)
  uint64_t items = 0;    // items taken in (frame markers excluded)
  uint64_t emitted = 0;  // items handed on
  double flops = 0;      // arithmetic done (front-end stages and preparer)
  double busy_s = 0;     // computing
  double starved_s = 0;  // waiting for an item (from time 0: the pipeline's fill counts)
  double blocked_s = 0;  // waiting for room in the next FIFO
  StageSeries series;    // the three over modeled time (starved, busy, blocked per bin)
  // Modeled time the stage took each frame's begin marker in and handed its
  // end marker on: frames overlap where one's begin precedes another's end.
  std::vector<double> frame_begin_s, frame_end_s;
};

}  // namespace girtd
