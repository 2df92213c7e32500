#include "fifo/fifo_word.hpp"

#include "config/rtl_widths.hpp"

namespace girtd {

FifoWordLayout fifo_word_layout(const Params& p) {
  // Packed from Z (least significant) up to X.
  FifoWordLayout f;
  const int screen_bits = bits_for(uint64_t(p.screen_width));
  int lsb = 0;
  for (BitField* field : {&f.z, &f.nf, &f.b, &f.g, &f.r, &f.y, &f.x}) {
    field->lsb = lsb;
    field->width = field == &f.z ? p.ep_z.out_bits
                   : field == &f.nf ? p.norm_frac_bits + 1  // 1.8: 256 is 1.0
                   : (field == &f.x || field == &f.y) ? screen_bits
                                                       : p.ep_color.out_bits;
    lsb += field->width;
  }
  f.width = lsb;
  return f;
}

int fifo_count_bits(const Params& p) { return bits_for(uint64_t(p.fifo_max_depth) + 1); }

}  // namespace girtd
