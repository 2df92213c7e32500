// What the hardware's words and addresses look like for a configuration:
// the DDA -> HAD FIFO word, the cache page, the VRAM word and address, the
// widths of counts and states. All derived from Params, never stored:
// config/girtd.json holds only the free choices. The same numbers go into
// the SystemVerilog package (rtl_package.hpp), the RTL drivers and the
// timing model.
#pragma once

#include <cstdint>

#include "config/params.hpp"

namespace girtd {

// Widths of the RTL's run-time timing ports and its counters: design
// choices, and the limits params.cpp holds the timings to.
inline constexpr int kRtlDdaPeriodBits = 8;   // dda.clock_ns, in base ticks
inline constexpr int kRtlTimeBits = 16;       // HAD access and blend, VRAM cycle
inline constexpr int kRtlLongTimeBits = 24;   // the frame clear, the steal period
inline constexpr int kRtlCountBits = 32;      // pixel and miss counters
inline constexpr int kRtlTickCountBits = 48;  // clock and tick counters
inline constexpr int kRtlQExponentBits = 4;   // Q = 2^k, k = -4..3 (signed), on the DDA's parameter port

inline constexpr int64_t max_of_bits(int bits) { return (int64_t{1} << bits) - 1; }

struct BitField {
  int lsb = 0;
  int width = 0;
  int msb() const { return lsb + width - 1; }
};

// One pixel in the FIFO, most significant field first: X, Y, R, G, B, nf, Z.
struct FifoWordLayout {
  BitField x, y, r, g, b, nf, z;
  int width = 0;
};

// A cache page: page_width x page_height pixels moved by one VRAM
// random-port cycle (one pixel per VRAM board). The page number is
// {Y[9:y_bits], X[9:x_bits]}, the pixel in the page {Y[y_bits-1:0], X[x_bits-1:0]}.
struct PageGeometry {
  int width_px = 0, height_px = 0;
  int x_bits = 0, y_bits = 0;  // log2 of the above
  int pixels = 0;              // per page
  int index_bits = 0;          // x_bits + y_bits
  int number_bits = 0;         // 2 x screen bits - index_bits
  int screen_bits = 0;

  uint32_t number_of(int x, int y) const {
    return (uint32_t(y >> y_bits) << (screen_bits - x_bits)) | uint32_t(x >> x_bits);
  }
  uint32_t index_of(int x, int y) const {
    return (uint32_t(y & ((1 << y_bits) - 1)) << x_bits) | uint32_t(x & ((1 << x_bits) - 1));
  }
  // The VRAM word of pixel (x, y): {page number, index}.
  uint32_t vram_address(int x, int y) const { return (number_of(x, y) << index_bits) | index_of(x, y); }
};

// A VRAM word: two RGB buffers and Z; a cached pixel: the back buffer's RGB and Z.
struct VramWordLayout {
  BitField rgb0, rgb1, z;  // rgb0 is shown while the front flag is 0
  int width = 0;
  int cell_bits = 0;       // a pixel in the cache: RGB and Z
};

// The HAD's cache: `pages` slots, direct-mapped (page P in slot P mod pages).
struct CacheGeometry {
  int pages = 1;
  int slot_bits = 1;  // a slot number (at least one bit, for the RTL's ports)
  int slot_of(uint32_t page_number) const { return static_cast<int>(page_number % uint32_t(pages)); }
};

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

// The frame clear through the VRAM's serial port, in base ticks, as hw/vram
// takes it (a clear of 0 ticks takes 1).
inline uint64_t frame_clear_ticks(const Params& p) {
  const uint64_t t = uint64_t(p.vram_serial_transfers) * uint64_t(p.ticks(p.vram_serial_ns) + p.ticks(p.vram_cycle_ns));
  return t ? t : 1;
}

// ceil(log2(n)) for n >= 1: the bits that count 0 .. n - 1.
int bits_for(uint64_t n);

}  // namespace girtd
