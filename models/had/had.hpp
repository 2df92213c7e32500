// Golden HAD (display update, §6 and the thesis' HadPix, §11): off-screen
// pixels and nf = 0 are dropped, Z < Zb passes, nf = 1 writes R, G, B and Z,
// 0 < nf < 1 blends R, G, B and keeps Z.
#pragma once

#include <algorithm>
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
inline uint8_t blend_channel(uint8_t c, uint8_t cb, int nf, OneMinusNf rule) {
  const int one_minus = (rule == OneMinusNf::kExact) ? (kNfOne - nf) : (0xFF & ~nf);
  const int sum = ((c * nf) >> 8) + ((cb * one_minus) >> 8);
  return static_cast<uint8_t>(sum > 255 ? 255 : sum);
}

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
  HadOutcome update(const Pixel& p, int layer = -1, bool covered = false) {
    return view().update(counts_, p, layer, covered);
  }
  // update() for each pixel of a run along one row (the DDA model's span
  // path, on golden and approx): run.size() pixels from x_first() to x_last() on row y(), each
  // from run.next() (.pixel, .covered). The screen test is made once for
  // the run where it holds for all; a run of covered opaque pixels
  // (run.covered_opaque()) gets the same update with nf and covered fixed. The HAD's state and the run are local
  // copies, which the compiler can keep in registers while pixels are written.
  // `told(x, y, outcome)` hears each pixel's outcome, in run order (the
  // approx back end's timing model); the default hears nothing. (Not the
  // Pixel: passing it made the compiler copy it through memory per pixel.)
  struct TellNothing {
    void operator()(int, int, HadOutcome) const {}
  };
  template <typename Run, typename Told = TellNothing>
  [[gnu::always_inline]] void update_run(const Run& pixels, int layer, Told told = {}) {
    Run run = pixels;
    const View v = view();
    HadCounts counts = counts_;
    const int64_t n = run.size();
    const int y = run.y(), x_lo = std::min(run.x_first(), run.x_last()), x_hi = std::max(run.x_first(), run.x_last());
    if (v.on_screen(x_lo, y) && v.on_screen(x_hi, y)) {
      if (y + 1 < v.screen_height) {  // the DDA's next row is below this one: start loading its ends
        __builtin_prefetch(&v.z[v.at(x_lo, y + 1)]);
        __builtin_prefetch(&v.z[v.at(x_hi, y + 1)]);
        __builtin_prefetch(&v.rgb[v.at(x_lo, y + 1)]);
        __builtin_prefetch(&v.rgb[v.at(x_hi, y + 1)]);
      }
      if (run.covered_opaque()) {  // the same update, with nf and covered known to the compiler
        for (int64_t k = 0; k < n; ++k) {
          Pixel p = run.next().pixel;
          p.nf = kNfOne;
          told(p.x, p.y, v.update_on_screen(counts, p, layer, true));
        }
      } else {
        for (int64_t k = 0; k < n; ++k) {
          const auto e = run.next();
          told(e.pixel.x, e.pixel.y, v.update_on_screen(counts, e.pixel, layer, e.covered));
        }
      }
    } else {
      for (int64_t k = 0; k < n; ++k) {
        const auto e = run.next();
        told(e.pixel.x, e.pixel.y, v.update(counts, e.pixel, layer, e.covered));
      }
    }
    counts_ = counts;
  }
  const HadCounts& counts() const { return counts_; }

 private:
  // What an update reads: the back buffer's planes as raw pointers (the
  // frame buffer swaps between updates, not during) and the settings.
  struct View {
    Rgb* rgb;
    uint16_t* z;
    int32_t* blender;
    size_t width;
    int screen_width, screen_height;
    OneMinusNf rule;
    bool drop_partial;

    bool on_screen(int x, int y) const { return x >= 0 && y >= 0 && x < screen_width && y < screen_height; }
    size_t at(int x, int y) const { return static_cast<size_t>(y) * width + static_cast<size_t>(x); }
    HadOutcome update(HadCounts& counts, const Pixel& p, int layer, bool covered) const {
      // Order as in HadPix: screen test, depth test, then nf.
      if (!on_screen(p.x, p.y)) {
        ++counts.dropped;
        return HadOutcome::kDropped;
      }
      return update_on_screen(counts, p, layer, covered);
    }
    HadOutcome update_on_screen(HadCounts& counts, const Pixel& p, int layer, bool covered) const;
  };
  View view() const {
    return {&fb_.back_rgb(0, 0), &fb_.z(0, 0),   &fb_.last_blender(0, 0), static_cast<size_t>(fb_.width()),
            screen_width_,       screen_height_, rule_,                   drop_partial_};
  }

  FrameBuffer& fb_;
  OneMinusNf rule_;
  int screen_width_, screen_height_;
  bool drop_partial_ = false;
  HadCounts counts_;
};

// The depth test, then nf (the screen test passed). Always inline: the
// golden DDA's span path calls it once per pixel, from four kinds of run.
[[gnu::always_inline]] inline HadOutcome Had::View::update_on_screen(HadCounts& counts, const Pixel& p, int layer,
                                                               bool covered) const {
  const size_t i = at(p.x, p.y);
  uint16_t& zb = z[i];
  if (!(p.z < zb)) {
    ++counts.z_rejected;
    return HadOutcome::kZRejected;
  }
  if (p.nf == 0) {
    ++counts.dropped;
    return HadOutcome::kDropped;
  }
  Rgb& cb = rgb[i];
  if (p.nf < kNfOne && drop_partial) {
    ++counts.dropped;
    return HadOutcome::kDropped;
  }
  if (p.nf >= kNfOne) {
    cb = Rgb{p.r, p.g, p.b};
    zb = p.z;
    ++counts.written;
    return HadOutcome::kWritten;
  }
  cb.r = blend_channel(p.r, cb.r, p.nf, rule);
  cb.g = blend_channel(p.g, cb.g, p.nf, rule);
  cb.b = blend_channel(p.b, cb.b, p.nf, rule);
  ++counts.blended;
  if (layer >= 0) {  // the plane holds layer << 1 | covered
    int32_t& last = blender[i];
    counts.reblended += last >= 0 && (last >> 1) == layer && (covered || (last & 1));
    last = layer << 1 | int32_t{covered};
  }
  return HadOutcome::kBlended;
}

}  // namespace girtd
