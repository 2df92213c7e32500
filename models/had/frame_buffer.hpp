// GIRTD's video memory seen functionally: two RGB buffers (double buffering)
// and one Z buffer, 1024 x 1024 (§7). The HAD draws into the back buffer;
// swap() shows it. Address = Y(10):X(10).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/types.hpp"

namespace girtd {

class FrameBuffer {
 public:
  FrameBuffer(int width, int height, uint16_t z_clear);

  int width() const { return width_; }
  int height() const { return height_; }
  bool on_screen(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  // Clears the back buffer to `background` and Z to the clear depth.
  void clear_back(Rgb background);
  void swap() { front_ ^= 1; }

  Rgb& back_rgb(int x, int y) { return rgb_[front_ ^ 1][index(x, y)]; }
  uint16_t& z(int x, int y) { return z_[index(x, y)]; }
  const Rgb& shown_rgb(int x, int y) const { return rgb_[front_][index(x, y)]; }
  uint16_t z_at(int x, int y) const { return z_[index(x, y)]; }
  // Not video memory: the layer (seam_layer) that last blended each pixel this frame
  // (-1: none), for counting seams (Had::update).
  int32_t& last_blender(int x, int y) { return blender_[index(x, y)]; }

  // Raw RGB bytes of the shown buffer, row-major (what image_sha256 hashes).
  std::vector<uint8_t> shown_bytes() const;
  std::vector<uint16_t> z_plane() const { return z_; }

 private:
  size_t index(int x, int y) const { return static_cast<size_t>(y) * width_ + x; }
  int width_, height_;
  uint16_t z_clear_;
  int front_ = 0;
  std::vector<Rgb> rgb_[2];
  std::vector<uint16_t> z_;
  std::vector<int32_t> blender_;
};

}  // namespace girtd
