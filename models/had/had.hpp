// Golden HAD (display update, §6 and the thesis' HadPix, §11): off-screen
// pixels and nf = 0 are dropped, Z < Zb passes, nf = 1 writes R, G, B and Z,
// 0 < nf < 1 blends R, G, B and keeps Z.
#pragma once

#include <cstdint>

#include "common/types.hpp"
#include "config/params.hpp"
#include "had/frame_buffer.hpp"

namespace girtd {

enum class HadOutcome { kWritten, kBlended, kZRejected, kDropped };

struct HadCounts {
  uint64_t written = 0, blended = 0, z_rejected = 0, dropped = 0;
  // Not an outcome: seams. Blends of a pixel its layer (a surface's faces
  // turned the same way) had already blended this frame, where one of the two
  // covered the pixel (inside its triangle: not in a fringe, not on a soft
  // edge): a shared edge drawn twice, or a neighbour's fringe over a
  // triangle. Two fringes over each other at a silhouette's corner, or two
  // triangles meeting on a silhouette, are per-edge antialiasing, not a seam,
  // and not counted.
  uint64_t reblended = 0;
  uint64_t total() const { return written + blended + z_rejected + dropped; }
};

// Cb = C nf + Cb (1 - nf) with 8 x 8 multiplies that keep the high byte; the
// two products are truncated separately, as the hardware adds two bytes.
// `nf` is 1..255 (0.8); 1 - nf is exact (256 - nf) or the inverted bits (255 - nf).
uint8_t blend_channel(uint8_t c, uint8_t cb, int nf, OneMinusNf rule);

class Had {
 public:
  Had(FrameBuffer& fb, OneMinusNf rule)
      : fb_(fb), rule_(rule), screen_width_(fb.width()), screen_height_(fb.height()) {}

  // The visible screen (pixels outside it are dropped): the whole frame
  // buffer, or the thesis program's 128 x 96 in its top-left corner.
  void set_screen(int width, int height) {
    screen_width_ = width;
    screen_height_ = height;
  }
  // The thesis program's QQ switch: antialiasing off, so every pixel with
  // nf < 1 is dropped instead of blended.
  void set_drop_partial(bool drop) { drop_partial_ = drop; }

  // For `reblended`: `layer`, the triangle's seam_layer() (-1: not known);
  // `covered`, the pixel is inside the triangle, not in its fringe.
  HadOutcome update(const Pixel& p, int layer = -1, bool covered = false);
  const HadCounts& counts() const { return counts_; }

 private:
  FrameBuffer& fb_;
  OneMinusNf rule_;
  int screen_width_, screen_height_;
  bool drop_partial_ = false;
  HadCounts counts_;
};

}  // namespace girtd
