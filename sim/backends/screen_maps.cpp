#include "backends/screen_maps.hpp"

#include <algorithm>
#include <stdexcept>

namespace girtd {

ScreenMapRecorder::ScreenMapRecorder(const Params& p, size_t log_entries)
    : layout_(rtl_layout(p)), slot_page_(size_t(layout_.cache.pages), -1), log_entries_(log_entries) {
  m_.width = p.screen_width;
  m_.height = p.screen_height;
  m_.page_width_px = layout_.page.width_px;
  m_.page_height_px = layout_.page.height_px;
  m_.page_misses.assign(size_t(1) << layout_.page.number_bits, 0);
  m_.dda_waste.assign(size_t(p.screen_width) * size_t(p.screen_height), ScreenMaps::kNone);
  if (p.screen_width > 1024 || p.screen_height > 1024) throw std::logic_error("screen maps: the row log holds 10-bit X and Y");
  if (log_entries_ == 0) throw std::logic_error("screen maps: an empty log");
  // Allocated and touched here, before the run: no page faults in it.
  pending_.resize(log_entries_);
  pending_.clear();
  miss_log_.resize(log_entries_);
  miss_log_.clear();
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
  if (pending_.size() + drawn_.size() + 1 > log_entries_) take_logs();
  for (const Run& r : drawn_) {
    if (r.y < 0 || r.y >= m_.height || r.lo < 0 || r.hi >= m_.width)  // the DDA draws within the screen
      throw std::logic_error("screen maps: a row off the screen");
    pending_.push_back(row_entry(r.y, r.lo, r.hi));
  }
  pending_.push_back(kWasteTag | waste);
  drawn_.clear();
  run_ = Run{};
}

void ScreenMapRecorder::take_logs() const {
  for (uint32_t page : miss_log_) ++m_.page_misses[page];
  miss_log_.clear();
  size_t from = 0;  // the first row of the triangle being read
  for (size_t i = 0; i < pending_.size(); ++i) {
    if (!(pending_[i] & kWasteTag)) continue;
    const uint8_t waste = uint8_t(pending_[i]);
    for (size_t k = from; k < i; ++k) {
      const uint32_t e = pending_[k];
      const int y = int(e >> 20), lo = int((e >> 10) & 1023), hi = int(e & 1023);
      std::fill_n(m_.dda_waste.begin() + ptrdiff_t(y) * m_.width + lo, hi - lo + 1, waste);
    }
    from = i + 1;
  }
  pending_.clear();
}

}  // namespace girtd
