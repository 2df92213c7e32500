#include "had/had.hpp"

namespace girtd {

uint8_t blend_channel(uint8_t c, uint8_t cb, int nf, OneMinusNf rule) {
  const int one_minus = (rule == OneMinusNf::kExact) ? (kNfOne - nf) : (0xFF & ~nf);
  const int sum = ((c * nf) >> 8) + ((cb * one_minus) >> 8);
  return static_cast<uint8_t>(sum > 255 ? 255 : sum);
}

HadOutcome Had::update(const Pixel& p, int layer, bool covered) {
  // Order as in HadPix: screen test, depth test, then nf.
  if (p.x < 0 || p.y < 0 || p.x >= screen_width_ || p.y >= screen_height_) {
    ++counts_.dropped;
    return HadOutcome::kDropped;
  }
  uint16_t& zb = fb_.z(p.x, p.y);
  if (!(p.z < zb)) {
    ++counts_.z_rejected;
    return HadOutcome::kZRejected;
  }
  if (p.nf == 0) {
    ++counts_.dropped;
    return HadOutcome::kDropped;
  }
  Rgb& cb = fb_.back_rgb(p.x, p.y);
  if (p.nf < kNfOne && drop_partial_) {
    ++counts_.dropped;
    return HadOutcome::kDropped;
  }
  if (p.nf >= kNfOne) {
    cb = Rgb{p.r, p.g, p.b};
    zb = p.z;
    ++counts_.written;
    return HadOutcome::kWritten;
  }
  cb.r = blend_channel(p.r, cb.r, p.nf, rule_);
  cb.g = blend_channel(p.g, cb.g, p.nf, rule_);
  cb.b = blend_channel(p.b, cb.b, p.nf, rule_);
  ++counts_.blended;
  if (layer >= 0) {  // the plane holds layer << 1 | covered
    int32_t& last = fb_.last_blender(p.x, p.y);
    counts_.reblended += last >= 0 && (last >> 1) == layer && (covered || (last & 1));
    last = layer << 1 | int32_t{covered};
  }
  return HadOutcome::kBlended;
}

}  // namespace girtd
