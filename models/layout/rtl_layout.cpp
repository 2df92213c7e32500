#include "layout/rtl_layout.hpp"

#include "dda/dda_engine.hpp"

namespace girtd {

RtlLayout rtl_layout(const Params& p) {
  RtlLayout l;
  l.screen_bits = bits_for(uint64_t(p.screen_width));
  l.fifo = fifo_word_layout(p);
  l.page = page_geometry(p);
  l.cache = cache_geometry(p);
  l.vram = vram_word_layout(p);
  l.fifo_count_bits = fifo_count_bits(p);
  l.dda_idle_state = static_cast<int>(DdaState::kCount);
  l.dda_state_bits = bits_for(uint64_t(l.dda_idle_state) + 1);
  return l;
}

}  // namespace girtd
