// What one pipeline stage did, in modeled seconds, and the occupancy of the
// FIFO in front of it. Plain C++ (no SystemC) so the report reads it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace girtd {

struct FifoActivity {
  uint64_t pushed = 0, popped = 0;
  uint64_t max_occupancy = 0;
  void push() {
    ++pushed;
    if (pushed - popped > max_occupancy) max_occupancy = pushed - popped;
  }
  void pop() { ++popped; }
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
  // Modeled time the stage took each frame's begin marker in and handed its
  // end marker on: frames overlap where one's begin precedes another's end.
  std::vector<double> frame_begin_s, frame_end_s;
};

}  // namespace girtd
