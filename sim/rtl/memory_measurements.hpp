// Measurements of the memory side on the RTL back end (hw/backend), for
// girtd claims: directed pixel streams against the thesis' cache formula
// t_med = t_acc + t_vram / nac (4.2.11.4), the frame clear, the end-to-end
// pixel rate on traces, and how long the DDA waits on a full FIFO.
#pragma once

#include <cstdint>
#include <string>

#include "config/params.hpp"

namespace girtd {

enum class PixelStream {
  kRow,     // 1024 pixels along a row: 16 per page (nac = 16)
  kColumn,  // 1024 pixels down a column: a new page every pixel (nac = 1)
};

struct StreamTiming {
  uint64_t pixels = 0, page_misses = 0;
  double ns_per_pixel = 0;
};

// From the end of the frame clear until the back end is idle again.
StreamTiming time_stream(const Params& p, PixelStream s);

// The serial-port frame clear, in microseconds.
double frame_clear_us(const Params& p);

struct TraceTiming {
  uint64_t pixels = 0;
  double seconds = 0;            // first triangle to idle, every frame (clears and swaps excluded)
  double dda_wait_fraction = 0;  // DDA clocks lost on a full FIFO / all DDA clocks
  int fifo_max = 0;
  double nac = 0;                // cache accesses per page miss
  double mpixels_per_s() const { return seconds > 0 ? double(pixels) / seconds / 1e6 : 0; }
};

// A triangle- or DDA-level trace through the whole RTL back end.
TraceTiming time_trace(const Params& p, const std::string& path);

}  // namespace girtd
