// The VRAM for a configuration: its word (two RGB buffers and Z) and the
// frame clear through its serial port (hw/vram, the timing model).
#pragma once

#include <cstdint>

#include "common/bit_field.hpp"
#include "config/params.hpp"

namespace girtd {

// A VRAM word: two RGB buffers and Z; a cached pixel: the back buffer's RGB and Z.
struct VramWordLayout {
  BitField rgb0, rgb1, z;  // rgb0 is shown while the front flag is 0
  int width = 0;
  int cell_bits = 0;       // a pixel in the cache: RGB and Z
};

VramWordLayout vram_word_layout(const Params& p);

// The frame clear through the VRAM's serial port, in base ticks, as hw/vram
// takes it (a clear of 0 ticks takes 1).
inline uint64_t frame_clear_ticks(const Params& p) {
  const uint64_t t = uint64_t(p.vram_serial_transfers) * uint64_t(p.ticks(p.vram_serial_ns) + p.ticks(p.vram_cycle_ns));
  return t ? t : 1;
}

}  // namespace girtd
