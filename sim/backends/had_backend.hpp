// A back end whose pixels go through the golden HAD into a frame buffer of
// its own (reference, golden, approx): the clear, the swap and the read-out
// are the same for each. The video memory exists before the run starts, as
// the hardware's does: allocating and first touching it is not drawing.
#pragma once

#include <cstdint>
#include <vector>

#include "backends/backend.hpp"
#include "config/params.hpp"
#include "had/frame_buffer.hpp"
#include "had/had.hpp"

namespace girtd {

class HadBackend : public Backend {
 public:
  explicit HadBackend(const Params& p)
      : fb_(p.screen_width, p.screen_height, static_cast<uint16_t>(p.depth_clear)), had_(fb_, p.one_minus_nf) {}
  void begin_frame(const FrameSettings& s) override {
    frame_ = s;
    fb_.clear_back(s.background);
    had_.set_drop_partial(s.qq);
  }
  void end_frame() override { fb_.swap(); }
  RgbImage shown() const override {
    RgbImage img;
    img.width = fb_.width();
    img.height = fb_.height();
    img.rgb = fb_.shown_bytes();
    return img;
  }
  std::vector<uint16_t> z_plane() const override { return fb_.z_plane(); }

 protected:
  FrameBuffer fb_;
  Had had_;
  FrameSettings frame_;  // the frame being drawn
};

}  // namespace girtd
