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

void ScreenMapRecorder::begin_frame() { std::fill(slot_page_.begin(), slot_page_.end(), -1); }

void ScreenMapRecorder::pixel(int x, int y) {
  const uint32_t page = layout_.page.number_of(x, y);
  int64_t& in_slot = slot_page_[size_t(layout_.cache.slot_of(page))];
  if (in_slot != int64_t(page)) {
    ++m_.page_misses[page];
    in_slot = page;
  }
  drawn_.push_back(uint32_t(y) * uint32_t(m_.width) + uint32_t(x));
}

void ScreenMapRecorder::end_triangle(uint64_t dda_cycles, uint64_t emitted) {
  const uint8_t waste = dda_cycles ? uint8_t(254 * (dda_cycles - std::min(emitted, dda_cycles)) / dda_cycles) : 0;
  for (uint32_t at : drawn_) m_.dda_waste[at] = waste;
  drawn_.clear();
}

}  // namespace girtd
