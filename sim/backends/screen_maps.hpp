// Where on the screen a back end spent its effort, for report.html's heat
// maps: the cache's page misses per page, and the share of DDA clocks each
// triangle wasted (states that emitted no pixel) over the pixels it drew.
// Fed with the pixels in the order the DDA emits them (pixel()): page misses
// follow from that order and the cache's geometry alone (direct-mapped, page
// P in slot P mod pages; empty at each frame's start, as the RTL's flush
// leaves it), not from timing, so the map is the same for golden's order,
// approx's and rtl's (one DDA, regressed bit for bit). rtl feeds the pixels
// its DDA pushes (rtl/rtl_screen_maps.hpp); approx feeds drawn() and takes
// the misses from its timing model (page_missed()). The [timing] tests check
// that the two give the same maps.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "config/params.hpp"
#include "layout/rtl_layout.hpp"

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
  // `log_entries`: the row log's size (below); a test makes it small.
  explicit ScreenMapRecorder(const Params& p, size_t log_entries = size_t(1) << 18);
  void begin_frame();  // the cache starts empty
  // On every pixel the RTL's DDA pushes: the page misses follow from the
  // cache's geometry here (inline: its cost is measured by `girtd bench --speed`).
  void pixel(int x, int y) {
    const uint32_t page = layout_.page.number_of(x, y);
    if (int64_t(page) != last_page_) page_change(page);  // the page just touched is still in its slot
    drawn(x, y);
  }
  // Where a timing model tells the misses itself (approx): each pixel drawn,
  // and each miss's page.
  void drawn(int x, int y) {
    // The DDA emits each row of a triangle once, as one streak of neighbours
    // (test_dda_properties.cpp): a row is its lowest and highest x.
    if (y != run_.y) [[unlikely]] {
      if (run_.y >= 0) drawn_.push_back(run_);
      run_ = {y, x, x};
    }
    run_.lo = std::min(run_.lo, x);
    run_.hi = std::max(run_.hi, x);
  }
  void page_missed(uint32_t page) {
    if (miss_log_.size() == log_entries_) take_logs();
    miss_log_.push_back(page);
  }
  void end_triangle(uint64_t dda_cycles, uint64_t emitted);
  const ScreenMaps& maps() const {
    take_logs();
    return m_;
  }

 private:
  void page_change(uint32_t page);  // a miss if the page's slot holds another
  RtlLayout layout_;
  std::vector<int64_t> slot_page_;  // -1: empty
  int64_t last_page_ = -1;          // the page of the last pixel
  struct Run {
    int y = -1, lo = 0, hi = 0;
  };
  Run run_;                         // the triangle's pixels: the run being extended,
  std::vector<Run> drawn_;          // and those before it

  // The maps are made from logs written in order: the waste map from the
  // triangles' rows, not row by row into the 1 MB map as each triangle
  // ends, and the page misses from the pages missed, not counted one by one
  // in the 256 kB map: those scattered lines would crowd the frame buffer
  // out of the cache during the run (approx on demo.trace: the series' cost
  // 5.5 -> 4.0 % with the row log). A log is taken into its map when it
  // fills and when the maps are read.
  void take_logs() const;
  size_t log_entries_;
  mutable std::vector<uint32_t> miss_log_;  // page numbers
  // One entry: a row {Y, lo X, hi X} (10 bits each: the 1024 x 1024 screen),
  // or, with kWasteTag, the waste of the rows logged since the last one.
  static constexpr uint32_t kWasteTag = uint32_t(1) << 31;
  static uint32_t row_entry(int y, int lo, int hi) { return uint32_t(y) << 20 | uint32_t(lo) << 10 | uint32_t(hi); }
  mutable std::vector<uint32_t> pending_;

  mutable ScreenMaps m_;
};

}  // namespace girtd
