#include "config/rtl_layout.hpp"

#include <algorithm>

#include "dda/dda_engine.hpp"

namespace girtd {

int bits_for(uint64_t n) {
  int b = 0;
  while ((uint64_t{1} << b) < n) ++b;
  return b;
}

RtlLayout rtl_layout(const Params& p) {
  RtlLayout l;
  l.screen_bits = bits_for(uint64_t(p.screen_width));

  // The FIFO word, packed from Z (least significant) up to X.
  FifoWordLayout& f = l.fifo;
  int lsb = 0;
  for (BitField* field : {&f.z, &f.nf, &f.b, &f.g, &f.r, &f.y, &f.x}) {
    field->lsb = lsb;
    field->width = field == &f.z ? p.ep_z.out_bits
                   : field == &f.nf ? p.norm_frac_bits + 1  // 1.8: 256 is 1.0
                   : (field == &f.x || field == &f.y) ? l.screen_bits
                                                       : p.ep_color.out_bits;
    lsb += field->width;
  }
  f.width = lsb;

  PageGeometry& g = l.page;
  g.width_px = p.cache_page_width;
  g.height_px = p.cache_page_height;
  g.x_bits = bits_for(uint64_t(g.width_px));
  g.y_bits = bits_for(uint64_t(g.height_px));
  g.pixels = g.width_px * g.height_px;
  g.index_bits = g.x_bits + g.y_bits;
  g.screen_bits = l.screen_bits;
  g.number_bits = 2 * l.screen_bits - g.index_bits;

  l.cache.pages = p.cache_pages;
  l.cache.slot_bits = std::max(1, bits_for(uint64_t(p.cache_pages)));

  const int rgb = 3 * p.ep_color.out_bits;
  l.vram.z = {0, p.ep_z.out_bits};
  l.vram.rgb1 = {l.vram.z.width, rgb};
  l.vram.rgb0 = {l.vram.rgb1.lsb + rgb, rgb};
  l.vram.width = l.vram.rgb0.lsb + rgb;
  l.vram.cell_bits = rgb + p.ep_z.out_bits;

  l.fifo_count_bits = bits_for(uint64_t(p.fifo_max_depth) + 1);
  l.dda_idle_state = static_cast<int>(DdaState::kCount);
  l.dda_state_bits = bits_for(uint64_t(l.dda_idle_state) + 1);
  return l;
}

}  // namespace girtd
