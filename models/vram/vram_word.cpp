#include "vram/vram_word.hpp"

namespace girtd {

VramWordLayout vram_word_layout(const Params& p) {
  VramWordLayout v;
  const int rgb = 3 * p.ep_color.out_bits;
  v.z = {0, p.ep_z.out_bits};
  v.rgb1 = {v.z.width, rgb};
  v.rgb0 = {v.rgb1.lsb + rgb, rgb};
  v.width = v.rgb0.lsb + rgb;
  v.cell_bits = rgb + p.ep_z.out_bits;
  return v;
}

}  // namespace girtd
