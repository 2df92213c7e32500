// A field of a hardware word: its least significant bit and its width.
#pragma once

namespace girtd {

struct BitField {
  int lsb = 0;
  int width = 0;
  int msb() const { return lsb + width - 1; }
};

}  // namespace girtd
