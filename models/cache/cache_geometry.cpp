#include "cache/cache_geometry.hpp"

#include <algorithm>

#include "config/rtl_widths.hpp"

namespace girtd {

PageGeometry page_geometry(const Params& p) {
  PageGeometry g;
  g.width_px = p.cache_page_width;
  g.height_px = p.cache_page_height;
  g.x_bits = bits_for(uint64_t(g.width_px));
  g.y_bits = bits_for(uint64_t(g.height_px));
  g.pixels = g.width_px * g.height_px;
  g.index_bits = g.x_bits + g.y_bits;
  g.screen_bits = bits_for(uint64_t(p.screen_width));
  g.number_bits = 2 * g.screen_bits - g.index_bits;
  return g;
}

CacheGeometry cache_geometry(const Params& p) {
  CacheGeometry c;
  c.pages = p.cache_pages;
  c.slot_bits = std::max(1, bits_for(uint64_t(p.cache_pages)));
  return c;
}

}  // namespace girtd
