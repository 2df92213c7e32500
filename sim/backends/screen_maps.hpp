// Where on the screen a back end spent its effort, for report.html's heat
// maps: the cache's page misses per page, and the share of DDA clocks each
// triangle wasted (states that emitted no pixel) over the pixels it drew.
// Fed with the pixels in the order the DDA emits them: page misses follow
// from that order and the cache's geometry alone (direct-mapped, page P in
// slot P mod pages; empty at each frame's start, as the RTL's flush leaves it), not from timing, so the
// map is the same for golden's order, approx's and rtl's (one DDA,
// regressed bit for bit).
#pragma once

#include <cstdint>
#include <vector>

#include "config/params.hpp"
#include "config/rtl_layout.hpp"

namespace girtd {

struct ScreenMaps {
  int width = 0, height = 0;  // the screen
  int page_width_px = 0, page_height_px = 0;
  std::vector<uint32_t> page_misses;  // by page number: {Y / page height, X / page width}, over the run
  // Per pixel (row-major): the share of its clocks the DDA wasted on the last
  // triangle drawn there, 0..254 for 0..100 %; kNone where none emitted.
  static constexpr uint8_t kNone = 255;
  std::vector<uint8_t> dda_waste;
};

class ScreenMapRecorder {
 public:
  explicit ScreenMapRecorder(const Params& p);
  void begin_frame();  // the cache starts empty
  void pixel(int x, int y);
  void end_triangle(uint64_t dda_cycles, uint64_t emitted);
  const ScreenMaps& maps() const { return m_; }

 private:
  RtlLayout layout_;
  std::vector<int64_t> slot_page_;  // -1: empty
  std::vector<uint32_t> drawn_;     // the triangle's pixels
  ScreenMaps m_;
};

}  // namespace girtd
