#include "had/frame_buffer.hpp"

#include <algorithm>

namespace girtd {

FrameBuffer::FrameBuffer(int width, int height, uint16_t z_clear)
    : width_(width), height_(height), z_clear_(z_clear) {
  const size_t n = static_cast<size_t>(width) * height;
  rgb_[0].assign(n, Rgb{});
  rgb_[1].assign(n, Rgb{});
  z_.assign(n, z_clear);
  blender_.assign(n, -1);
}

void FrameBuffer::clear_back(Rgb background) {
  std::fill(rgb_[front_ ^ 1].begin(), rgb_[front_ ^ 1].end(), background);
  std::fill(z_.begin(), z_.end(), z_clear_);
  std::fill(blender_.begin(), blender_.end(), -1);
}

std::vector<uint8_t> FrameBuffer::shown_bytes() const {
  std::vector<uint8_t> out;
  out.reserve(rgb_[front_].size() * 3);
  for (const Rgb& p : rgb_[front_]) {
    out.push_back(p.r);
    out.push_back(p.g);
    out.push_back(p.b);
  }
  return out;
}

}  // namespace girtd
