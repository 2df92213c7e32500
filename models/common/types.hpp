// Value types that cross stage boundaries: screen-space triangles (the
// preparer's input), frame settings, and the pixel the DDA hands the HAD.
#pragma once

#include <array>
#include <cstdint>

#include "girtd/design_constants.hpp"

namespace girtd {

// A screen-space vertex: x, y in pixels (y down, pixel (x, y) sampled at the
// lattice point (x, y)); z in 0..65535 depth units; r, g, b in 0..255;
// t the opacity 0..1 (the DDA's T; 1 = opaque).
struct Vertex {
  double x = 0, y = 0, z = 0, r = 0, g = 0, b = 0, t = 1;
};

struct Triangle {
  std::array<Vertex, 3> v;
  int source_line = 0;  // where it came from, for error messages
  // Bit i: the edge from v[i] to v[(i + 1) % 3] is shared with a neighbour
  // of the same surface (a triangulator diagonal or a mesh-interior edge),
  // so it needs no antialiasing fringe (thesis 5.2.4's invisible edges).
  uint8_t interior_edges = 0;
  int surface = -1;  // the front end's surface id (-1: not known), at most kMaxSurfaceId
};

// Surface ids up to here leave room for the seam counter's layer and flag bits.
inline constexpr int kMaxSurfaceId = (1 << 29) - 1;

// Inclusive pixel window (Xjmin..Xjmax, Yjmin..Yjmax of §3).
struct Window {
  int x0 = 0, y0 = 0, x1 = 1023, y1 = 1023;
  bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

// Per-frame settings a trace carries.
struct FrameSettings {
  Window window;
  Rgb background;
  double q = 1.0;  // antialiasing width Q (0 = off)
  int q_line = 0;  // trace line that set q (for error messages)
  bool qq = false;  // thesis program's QQ switch: antialiasing off, nf < 1 dropped
};

// nf is 1.8 fixed point: 1 << nf.norm_frac_bits (256) = 1.0.
inline constexpr int kNfOne = 1 << kNormFracBits;

// One pixel leaving the DDA (the 69-bit FIFO word, with full-width X, Y so
// the HAD can drop off-screen pixels of back ends that produce them).
struct Pixel {
  int x = 0, y = 0;
  uint8_t r = 0, g = 0, b = 0;
  uint16_t z = 0;
  uint16_t nf = 0;  // 0..256
};

}  // namespace girtd
