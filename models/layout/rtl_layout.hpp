// What the hardware's words and addresses look like for a configuration:
// every back-end stage's layout (models/fifo, models/cache, models/vram)
// and the widths of the DDA's state, gathered for the SystemVerilog package
// (rtl_package.hpp), the RTL drivers and the timing model. All derived
// from Params, never stored: config/girtd.json holds only the free choices.
#pragma once

#include "cache/cache_geometry.hpp"
#include "config/params.hpp"
#include "config/rtl_widths.hpp"
#include "fifo/fifo_word.hpp"
#include "vram/vram_word.hpp"

namespace girtd {

struct RtlLayout {
  int screen_bits = 0;       // X and Y of the 1024 x 1024 screen
  FifoWordLayout fifo;
  PageGeometry page;
  CacheGeometry cache;
  VramWordLayout vram;
  int fifo_count_bits = 0;   // 0 .. fifo.max_depth entries
  int dda_state_bits = 0;    // the DDA's states and IDLE
  int dda_idle_state = 0;
};

RtlLayout rtl_layout(const Params& p);

}  // namespace girtd
