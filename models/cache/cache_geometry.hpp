// The HAD's pixel cache for a configuration: what a page holds and which
// slot a page goes in (hw/cache, the timing model and the heat maps).
#pragma once

#include <cstdint>

#include "config/params.hpp"

namespace girtd {

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

// The HAD's cache: `pages` slots, direct-mapped (page P in slot P mod pages:
// its low bits, `pages` being a power of two as the config requires).
struct CacheGeometry {
  int pages = 1;
  int slot_bits = 1;  // a slot number (at least one bit, for the RTL's ports)
  int slot_of(uint32_t page_number) const { return static_cast<int>(page_number & uint32_t(pages - 1)); }
};

PageGeometry page_geometry(const Params& p);
CacheGeometry cache_geometry(const Params& p);

}  // namespace girtd
