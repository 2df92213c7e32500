// The DDA -> HAD FIFO's word for a configuration (hw/fifo carries it, the
// RTL package and the drivers pack and unpack it).
#pragma once

#include "common/bit_field.hpp"
#include "config/params.hpp"

namespace girtd {

// One pixel in the FIFO, most significant field first: X, Y, R, G, B, nf, Z.
struct FifoWordLayout {
  BitField x, y, r, g, b, nf, z;
  int width = 0;
};

FifoWordLayout fifo_word_layout(const Params& p);

// The bits of the FIFO's count, 0 .. fifo.max_depth entries.
int fifo_count_bits(const Params& p);

}  // namespace girtd
