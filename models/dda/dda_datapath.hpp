// The DDA's datapath: X and Y counters and the 8 adder EPs, each with its
// AUX register, performing one operation per clock. Shared by every
// sequencer (the hardware state machine and the thesis' DDApix).
#pragma once

#include <array>
#include <cstdint>

#include "common/fixed_point.hpp"
#include "config/params.hpp"
#include "common/types.hpp"
#include "dda/dda_params.hpp"

namespace girtd {

struct DdaRegisters {
  int x = 0, y = 0;
  std::array<int64_t, kEpCount> v{};
};

class DdaDatapath {
 public:
  DdaDatapath(const Params& p, const DdaParams& in) : in_(in), xy_bits_(p.xy_bits) {
    for (int i = 0; i < kEpCount; ++i) fmt_[i] = &p.ep_d;
    fmt_[kEpR] = fmt_[kEpG] = fmt_[kEpB] = &p.ep_color;
    fmt_[kEpT] = &p.ep_t;
    fmt_[kEpZ] = &p.ep_z;
    pix_.x = in.x0;
    pix_.y = in.y0;
    for (int i = 0; i < kEpCount; ++i) pix_.v[i] = wrap(in.ep[i].v, *fmt_[i]);
  }

  void step_x(int s) {
    pix_.x = static_cast<int>(wrap_to_bits(pix_.x + s, xy_bits_));
    for (int i = 0; i < kEpCount; ++i) pix_.v[i] = wrap(pix_.v[i] + s * in_.ep[i].dx, *fmt_[i]);
  }
  void step_y() {
    pix_.y = static_cast<int>(wrap_to_bits(pix_.y + 1, xy_bits_));
    for (int i = 0; i < kEpCount; ++i) pix_.v[i] = wrap(pix_.v[i] + in_.ep[i].dy, *fmt_[i]);
  }
  void save() { aux_ = pix_; }
  void restore() { pix_ = aux_; }

  const DdaRegisters& pix() const { return pix_; }
  const FixFormat& format(int ep) const { return *fmt_[ep]; }

 private:
  const DdaParams& in_;
  int xy_bits_;
  const FixFormat* fmt_[kEpCount];
  DdaRegisters pix_, aux_;
};

// The 69-bit FIFO word (plus full-width X, Y) from the registers as they
// stand: the EP output stages of fig. 4.20 and the nf the sequencer's nf unit
// made from them.
inline Pixel output_pixel(const DdaRegisters& r, const Params& p, int nf) {
  Pixel px;
  px.x = r.x;
  px.y = r.y;
  px.r = static_cast<uint8_t>(saturate_output(r.v[kEpR], p.ep_color));
  px.g = static_cast<uint8_t>(saturate_output(r.v[kEpG], p.ep_color));
  px.b = static_cast<uint8_t>(saturate_output(r.v[kEpB], p.ep_color));
  px.z = static_cast<uint16_t>(saturate_output(r.v[kEpZ], p.ep_z));
  px.nf = static_cast<uint16_t>(nf);
  return px;
}

}  // namespace girtd
