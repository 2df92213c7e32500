// Mesa's llvmpipe through OSMesa: an independent rasterizer for the picture
// yardstick (issue "Error against run time"). Draws opaque screen-space
// triangles with Gouraud colour and a Z test (GL_LESS, as the HAD), single
// threaded, offline. GL samples at pixel centres and GIRTD at lattice
// points, so every vertex moves by half a pixel: GIRTD's pixel (x, y) and
// GL's pixel (x, H - 1 - y) then test the same point.
#pragma once

#include <cstdint>
#include <vector>

#include "common/types.hpp"
#include "io/png_io.hpp"

namespace girtd {

struct LlvmpipeFrame {
  RgbImage rgb;              // GIRTD orientation (row 0 at the top)
  std::vector<uint16_t> z;   // depth units, z_clear where nothing was drawn
  double draw_s = 0;         // clear to glFinish: the triangles in memory to the final buffers (a second
                             // pass: the first, untimed, compiled llvmpipe's shaders)
};

// Depth 0..65535 maps onto GL's 0..1; the buffer is cleared to z_clear
// (config depth.clear). Throws std::runtime_error when OSMesa cannot make a
// context.
LlvmpipeFrame render_llvmpipe(const std::vector<Triangle>& triangles, int width, int height, Rgb background,
                              uint16_t z_clear);

}  // namespace girtd
