#include "backends/screen_maps.hpp"

#include <algorithm>

namespace girtd {

ScreenMapRecorder::ScreenMapRecorder(const Params& p)
    : layout_(rtl_layout(p)), slot_page_(size_t(layout_.cache.pages), -1) {
  m_.width = p.screen_width;
  m_.height = p.screen_height;
  m_.page_width_px = layout_.page.width_px;
  m_.page_height_px = layout_.page.height_px;
  m_.page_misses.assign(size_t(1) << layout_.page.number_bits, 0);
  m_.dda_waste.assign(size_t(p.screen_width) * size_t(p.screen_height), ScreenMaps::kNone);
}

void ScreenMapRecorder::begin_frame() {
  std::fill(slot_page_.begin(), slot_page_.end(), -1);
  last_page_ = -1;
}

void ScreenMapRecorder::page_change(uint32_t page) {
  int64_t& in_slot = slot_page_[size_t(layout_.cache.slot_of(page))];
  if (in_slot != int64_t(page)) {
    page_missed(page);
    in_slot = page;
  }
  last_page_ = page;
}

void ScreenMapRecorder::end_triangle(uint64_t dda_cycles, uint64_t emitted) {
  const uint8_t waste = dda_cycles ? uint8_t(254 * (dda_cycles - std::min(emitted, dda_cycles)) / dda_cycles) : 0;
  if (run_.y >= 0) drawn_.push_back(run_);
  for (const Run& r : drawn_)
    std::fill_n(m_.dda_waste.begin() + ptrdiff_t(r.y) * m_.width + r.lo, r.hi - r.lo + 1, waste);
  drawn_.clear();
  run_ = Run{};
}

}  // namespace girtd
