// Unit tests for the golden HAD (models/had/had.hpp) and the frame buffer
// (models/had/frame_buffer.hpp). Blend results are worked out by hand:
// Cb' = (C nf >> 8) + (Cb (1 - nf) >> 8), 1 - nf = 256 - nf (exact) or
// 255 - nf (invert_bits).
#include <catch2/catch.hpp>

#include <utility>
#include <vector>

#include "had/frame_buffer.hpp"
#include "had/had.hpp"

namespace girtd {
namespace {

constexpr uint16_t kZClear = 65535;  // depth.clear of config/girtd.json

Pixel px(int x, int y, uint8_t r, uint8_t g, uint8_t b, uint16_t z, uint16_t nf) {
  Pixel p;
  p.x = x;
  p.y = y;
  p.r = r;
  p.g = g;
  p.b = b;
  p.z = z;
  p.nf = nf;
  return p;
}

}  // namespace

TEST_CASE("HAD depth test is strict: Z < Zb writes, equal Z is rejected", "[had]") {
  FrameBuffer fb(1024, 1024, kZClear);
  Had had(fb, OneMinusNf::kExact);
  // Cleared Z is 65535: a pixel at 65535 is not nearer -> rejected.
  CHECK(had.update(px(5, 5, 1, 2, 3, 65535, 256)) == HadOutcome::kZRejected);
  CHECK(fb.back_rgb(5, 5) == Rgb{0, 0, 0});
  // 1000 < 65535 -> written.
  CHECK(had.update(px(5, 5, 10, 20, 30, 1000, 256)) == HadOutcome::kWritten);
  CHECK(fb.z_at(5, 5) == 1000);
  // Equal Z (1000 < 1000 is false) -> rejected, colour unchanged.
  CHECK(had.update(px(5, 5, 99, 99, 99, 1000, 256)) == HadOutcome::kZRejected);
  CHECK(fb.back_rgb(5, 5) == Rgb{10, 20, 30});
  // Farther -> rejected.
  CHECK(had.update(px(5, 5, 99, 99, 99, 1001, 256)) == HadOutcome::kZRejected);
  // One unit nearer -> written.
  CHECK(had.update(px(5, 5, 40, 50, 60, 999, 256)) == HadOutcome::kWritten);
  CHECK(fb.back_rgb(5, 5) == Rgb{40, 50, 60});
  CHECK(fb.z_at(5, 5) == 999);
  // The depth test also guards blending: a farther translucent pixel is rejected.
  CHECK(had.update(px(5, 5, 0, 0, 0, 2000, 128)) == HadOutcome::kZRejected);
  CHECK(fb.back_rgb(5, 5) == Rgb{40, 50, 60});
  CHECK(had.counts().written == 2);
  CHECK(had.counts().z_rejected == 4);
}

TEST_CASE("HAD nf = 256 writes R, G, B and Z", "[had]") {
  FrameBuffer fb(1024, 1024, kZClear);
  fb.clear_back(Rgb{9, 9, 9});
  Had had(fb, OneMinusNf::kExact);
  CHECK(had.update(px(100, 200, 255, 128, 7, 12345, 256)) == HadOutcome::kWritten);
  CHECK(fb.back_rgb(100, 200) == Rgb{255, 128, 7});
  CHECK(fb.z_at(100, 200) == 12345);
  // Neighbours untouched.
  CHECK(fb.back_rgb(101, 200) == Rgb{9, 9, 9});
  CHECK(fb.back_rgb(100, 201) == Rgb{9, 9, 9});
  CHECK(fb.z_at(101, 200) == kZClear);
  CHECK(had.counts().written == 1);
  CHECK(had.counts().total() == 1);
}

TEST_CASE("HAD nf = 0 drops the pixel and changes nothing", "[had]") {
  FrameBuffer fb(1024, 1024, kZClear);
  fb.clear_back(Rgb{1, 2, 3});
  Had had(fb, OneMinusNf::kExact);
  CHECK(had.update(px(7, 8, 200, 200, 200, 100, 0)) == HadOutcome::kDropped);
  CHECK(fb.back_rgb(7, 8) == Rgb{1, 2, 3});
  CHECK(fb.z_at(7, 8) == kZClear);
  CHECK(had.counts().dropped == 1);
  CHECK(had.counts().written == 0);
  CHECK(had.counts().blended == 0);
  CHECK(had.counts().z_rejected == 0);
}

TEST_CASE("HAD blends R, G, B with exact 1 - nf and keeps Z", "[had]") {
  FrameBuffer fb(1024, 1024, kZClear);
  Had had(fb, OneMinusNf::kExact);
  // Background pixel: Cb = (100, 255, 255), Zb = 5000.
  REQUIRE(had.update(px(3, 4, 100, 255, 255, 5000, 256)) == HadOutcome::kWritten);
  // nf = 128 (0.5), 1 - nf = 128:
  //   R: (200*128 >> 8) + (100*128 >> 8) = 25600>>8 + 12800>>8 = 100 + 50 = 150
  //   G: (  0*128 >> 8) + (255*128 >> 8) = 0 + 32640>>8 = 0 + 127      = 127
  //   B: (255*128 >> 8) + (255*128 >> 8) = 127 + 127                  = 254
  CHECK(had.update(px(3, 4, 200, 0, 255, 4000, 128)) == HadOutcome::kBlended);
  CHECK(fb.back_rgb(3, 4) == Rgb{150, 127, 254});
  CHECK(fb.z_at(3, 4) == 5000);  // Z kept, not 4000
  CHECK(had.counts().blended == 1);
  // A second blend on top, nf = 64 (0.25), 1 - nf = 192, C = (0, 255, 10):
  //   R: 0 + (150*192 >> 8) = 28800>>8 = 112
  //   G: (255*64 >> 8) + (127*192 >> 8) = 16320>>8 + 24384>>8 = 63 + 95 = 158
  //   B: (10*64 >> 8) + (254*192 >> 8) = 640>>8 + 48768>>8 = 2 + 190 = 192
  CHECK(had.update(px(3, 4, 0, 255, 10, 4999, 64)) == HadOutcome::kBlended);
  CHECK(fb.back_rgb(3, 4) == Rgb{112, 158, 192});
  CHECK(fb.z_at(3, 4) == 5000);
}

TEST_CASE("HAD blends with invert_bits 1 - nf = 255 - nf", "[had]") {
  FrameBuffer fb(1024, 1024, kZClear);
  Had had(fb, OneMinusNf::kInvertBits);
  REQUIRE(had.update(px(3, 4, 100, 255, 255, 5000, 256)) == HadOutcome::kWritten);
  // nf = 128, 1 - nf = ~128 & 0xFF = 127:
  //   R: (200*128 >> 8) + (100*127 >> 8) = 100 + 12700>>8 = 100 + 49 = 149
  //   G: 0 + (255*127 >> 8) = 32385>>8 = 126
  //   B: 127 + 126 = 253
  CHECK(had.update(px(3, 4, 200, 0, 255, 4000, 128)) == HadOutcome::kBlended);
  CHECK(fb.back_rgb(3, 4) == Rgb{149, 126, 253});
  CHECK(fb.z_at(3, 4) == 5000);
}

TEST_CASE("blend_channel edge values of nf for both 1 - nf rules", "[had]") {
  // nf = 1: exact: (255*1 >> 8) + (255*255 >> 8) = 0 + 65025>>8 = 0 + 254 = 254.
  CHECK(blend_channel(255, 255, 1, OneMinusNf::kExact) == 254);
  // nf = 1: invert: 1 - nf = 254: 0 + (255*254 >> 8) = 64770>>8 = 253.
  CHECK(blend_channel(255, 255, 1, OneMinusNf::kInvertBits) == 253);
  // nf = 255: exact: (255*255 >> 8) + (255*1 >> 8) = 254 + 0 = 254.
  CHECK(blend_channel(255, 255, 255, OneMinusNf::kExact) == 254);
  // nf = 255: invert: 1 - nf = 0: 254 + 0 = 254.
  CHECK(blend_channel(255, 255, 255, OneMinusNf::kInvertBits) == 254);
  // nf = 255 over black with C = 0: 0.
  CHECK(blend_channel(0, 0, 255, OneMinusNf::kExact) == 0);
  // nf = 192, C = 100, Cb = 40: (19200>>8) + (40*64>>8) = 75 + 10 = 85.
  CHECK(blend_channel(100, 40, 192, OneMinusNf::kExact) == 85);
  // invert: 1 - nf = 63: 75 + (2520>>8) = 75 + 9 = 84.
  CHECK(blend_channel(100, 40, 192, OneMinusNf::kInvertBits) == 84);
}

TEST_CASE("HAD drops off-screen pixels without touching memory", "[had]") {
  FrameBuffer fb(1024, 1024, kZClear);
  Had had(fb, OneMinusNf::kExact);
  CHECK(had.update(px(-1, 0, 255, 255, 255, 0, 256)) == HadOutcome::kDropped);
  CHECK(had.update(px(1024, 0, 255, 255, 255, 0, 256)) == HadOutcome::kDropped);
  CHECK(had.update(px(0, -1, 255, 255, 255, 0, 256)) == HadOutcome::kDropped);
  CHECK(had.update(px(0, 1024, 255, 255, 255, 0, 256)) == HadOutcome::kDropped);
  CHECK(had.update(px(-5000, 70000, 255, 255, 255, 0, 256)) == HadOutcome::kDropped);
  CHECK(had.counts().dropped == 5);
  // The screen corners themselves are on screen.
  CHECK(had.update(px(0, 0, 1, 1, 1, 0, 256)) == HadOutcome::kWritten);
  CHECK(had.update(px(1023, 1023, 2, 2, 2, 0, 256)) == HadOutcome::kWritten);
  CHECK(had.update(px(1023, 0, 3, 3, 3, 0, 256)) == HadOutcome::kWritten);
  CHECK(had.update(px(0, 1023, 4, 4, 4, 0, 256)) == HadOutcome::kWritten);
  // Nothing else changed: the buffer holds exactly the four corner writes.
  fb.swap();
  const std::vector<uint8_t> bytes = fb.shown_bytes();
  size_t nonzero = 0;
  for (uint8_t b : bytes) nonzero += (b != 0);
  CHECK(nonzero == 4 * 3);
  CHECK(fb.shown_rgb(0, 0) == Rgb{1, 1, 1});
  CHECK(fb.shown_rgb(1023, 1023) == Rgb{2, 2, 2});
  CHECK(fb.shown_rgb(1023, 0) == Rgb{3, 3, 3});
  CHECK(fb.shown_rgb(0, 1023) == Rgb{4, 4, 4});
}

TEST_CASE("HAD counters add up to the pixels offered", "[had]") {
  FrameBuffer fb(1024, 1024, kZClear);
  Had had(fb, OneMinusNf::kExact);
  had.update(px(10, 10, 1, 1, 1, 100, 256));   // written
  had.update(px(11, 10, 1, 1, 1, 100, 256));   // written
  had.update(px(10, 10, 1, 1, 1, 100, 256));   // z rejected (equal)
  had.update(px(10, 10, 1, 1, 1, 50, 100));    // blended
  had.update(px(12, 10, 1, 1, 1, 50, 1));      // blended (on the cleared pixel)
  had.update(px(12, 10, 1, 1, 1, 50, 0));      // dropped (nf = 0)
  had.update(px(2000, 10, 1, 1, 1, 50, 256));  // dropped (off screen)
  had.update(px(11, 10, 1, 1, 1, 200, 256));   // z rejected (farther)
  const HadCounts& c = had.counts();
  CHECK(c.written == 2);
  CHECK(c.blended == 2);
  CHECK(c.z_rejected == 2);
  CHECK(c.dropped == 2);
  CHECK(c.total() == 8);
  CHECK(c.written + c.blended + c.z_rejected + c.dropped == 8);
}

TEST_CASE("FrameBuffer clear_back sets the background and the clear depth", "[had]") {
  FrameBuffer fb(1024, 1024, kZClear);
  Had had(fb, OneMinusNf::kExact);
  had.update(px(50, 60, 200, 100, 50, 10, 256));
  REQUIRE(fb.z_at(50, 60) == 10);
  fb.clear_back(Rgb{7, 8, 9});
  for (auto [x, y] : {std::pair{0, 0}, std::pair{50, 60}, std::pair{1023, 1023}, std::pair{1023, 0},
                      std::pair{0, 1023}}) {
    CHECK(fb.back_rgb(x, y) == Rgb{7, 8, 9});
    CHECK(fb.z_at(x, y) == 65535);
  }
}

TEST_CASE("FrameBuffer swap shows the back buffer and shown_bytes is 1024x1024x3", "[had]") {
  FrameBuffer fb(1024, 1024, kZClear);
  Had had(fb, OneMinusNf::kExact);
  // Frame 1: background (1, 2, 3), one pixel drawn at (4, 5).
  fb.clear_back(Rgb{1, 2, 3});
  had.update(px(4, 5, 250, 251, 252, 10, 256));
  // Not shown yet: the front buffer is still the initial black.
  CHECK(fb.shown_rgb(4, 5) == Rgb{0, 0, 0});
  CHECK(fb.shown_rgb(0, 0) == Rgb{0, 0, 0});
  fb.swap();
  CHECK(fb.shown_rgb(4, 5) == Rgb{250, 251, 252});
  CHECK(fb.shown_rgb(0, 0) == Rgb{1, 2, 3});
  // shown_bytes: 1024 * 1024 * 3 = 3145728 bytes, row-major:
  // (4, 5) at (5 * 1024 + 4) * 3 = 15372.
  const std::vector<uint8_t> bytes = fb.shown_bytes();
  REQUIRE(bytes.size() == 3145728u);
  CHECK(bytes[15372] == 250);
  CHECK(bytes[15373] == 251);
  CHECK(bytes[15374] == 252);
  CHECK(bytes[0] == 1);
  CHECK(bytes[1] == 2);
  CHECK(bytes[2] == 3);
  // Frame 2 clears the other buffer: what is shown stays frame 1.
  fb.clear_back(Rgb{40, 41, 42});
  CHECK(fb.shown_rgb(4, 5) == Rgb{250, 251, 252});
  CHECK(fb.back_rgb(4, 5) == Rgb{40, 41, 42});
  fb.swap();
  CHECK(fb.shown_rgb(4, 5) == Rgb{40, 41, 42});
  CHECK(fb.shown_bytes()[15372] == 40);
}

}  // namespace girtd
