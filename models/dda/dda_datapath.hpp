// The DDA's datapath: X and Y counters and the 8 adder EPs, each with its
// AUX register, performing one operation per clock. Shared by every
// sequencer (the hardware state machine and the thesis' DDApix).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "common/fixed_point.hpp"
#include "config/params.hpp"
#include "common/types.hpp"
#include "dda/dda_params.hpp"
#include "dda/ep_numerics.hpp"

namespace girtd {

struct DdaRegisters {
  int x = 0, y = 0;
  std::array<int64_t, kEpCount> v{};
};

class DdaDatapath {
 public:
  static constexpr bool kExact = false;  // adders wrap: no spans
  // `shadow`: keep the wrap detector's registers; false only where no EP can
  // wrap (may_wrap), and then exact() is pix().
  DdaDatapath(const Params& p, const DdaParams& in, bool shadow = true)
      : in_(in), xy_bits_(p.xy_bits), shadow_(shadow) {
    for (int i = 0; i < kEpCount; ++i) fmt_[i] = &format_of(p, i);
    for (int i = 0; i < kEpCount; ++i) detect_bits_[i] = fmt_[i]->total_bits() + p.guard_bits(*fmt_[i]);
    pix_.x = in.x0;
    pix_.y = in.y0;
    for (int i = 0; i < kEpCount; ++i) pix_.v[i] = wrap(in.ep[i].v, *fmt_[i]);
    exact_ = pix_;
  }

  void step_x(int s) {
    pix_.x = static_cast<int>(wrap_to_bits(pix_.x + s, xy_bits_));
    for (int i = 0; i < kEpCount; ++i) add(i, s * in_.ep[i].dx);
  }
  void step_y() {
    pix_.y = static_cast<int>(wrap_to_bits(pix_.y + 1, xy_bits_));
    for (int i = 0; i < kEpCount; ++i) add(i, in_.ep[i].dy);
  }
  // The same registers with the wrap detector's guard bits (ep.wrap_guard_bits;
  // hw/dda/dda_ep.sv): where they differ, the hardware holds a wrapped value. (The adders are modular, so a value
  // that wraps and steps back is right again: only a wrapped value in use
  // changes the picture.)
  const DdaRegisters& exact() const { return shadow_ ? exact_ : pix_; }
  void save() {
    aux_ = pix_;
    if (shadow_) exact_aux_ = exact_;
  }
  void restore() {
    pix_ = aux_;
    if (shadow_) exact_ = exact_aux_;
  }

  const DdaRegisters& pix() const { return pix_; }
  const FixFormat& format(int ep) const { return *fmt_[ep]; }
  static const FixFormat& format_of(const Params& p, int ep) {
    if (ep == kEpR || ep == kEpG || ep == kEpB) return p.ep_color;
    if (ep == kEpT) return p.ep_t;
    if (ep == kEpZ) return p.ep_z;
    return p.ep_d;
  }

 private:
  // One EP's adder: W bits, wrapping like the hardware's.
  void add(int i, int64_t step) {
    pix_.v[i] = wrap(pix_.v[i] + step, *fmt_[i]);
    if (!shadow_) return;
    const uint64_t sum = static_cast<uint64_t>(exact_.v[i]) + static_cast<uint64_t>(step);  // modular, as the RTL's
    exact_.v[i] = wrap_to_bits(static_cast<int64_t>(sum), detect_bits_[i]);
  }

  const DdaParams& in_;
  int xy_bits_;
  bool shadow_;
  DdaRegisters exact_, exact_aux_;
  const FixFormat* fmt_[kEpCount];
  int detect_bits_[kEpCount];  // register width + guard bits
  DdaRegisters pix_, aux_;
};

// Whether an EP register can wrap while the DDA walks this triangle. Until
// one wraps, a register holds v0 + (X - x0) dX + (Y - y0) dY: linear, so its
// extremes over what the DDA can visit (X between the limits and the start,
// Y from the start to one row past Ymax) lie at the corners. When they fit
// every EP's format, nothing wraps and the wrap detector has nothing to see.
inline bool may_wrap(const Params& p, const DdaParams& in) {
  const int64_t xs[2] = {std::min(in.x0, in.xmin), std::max(in.x0, in.xmax)};
  const int64_t ys[2] = {in.y0, std::max(in.y0, in.ymax + 1)};
  for (int i = 0; i < kEpCount; ++i) {
    const FixFormat& f = DdaDatapath::format_of(p, i);
    const int64_t v0 = wrap(in.ep[i].v, f);  // the datapath starts from the wrapped value
    for (int64_t x : xs)
      for (int64_t y : ys) {
        const __int128 v = static_cast<__int128>(v0) + static_cast<__int128>(x - in.x0) * in.ep[i].dx +
                           static_cast<__int128>(y - in.y0) * in.ep[i].dy;
        if (v < f.raw_min() || v > f.raw_max()) return true;
      }
  }
  return false;
}

// Whether a triangle can use ExactDatapath: no EP can wrap (may_wrap), and
// neither can X or Y over the pixels the DDA can visit.
inline bool exact_steps(const Params& p, const DdaParams& in) {
  const int64_t lo = -(int64_t{1} << (p.xy_bits - 1)), hi = (int64_t{1} << (p.xy_bits - 1)) - 1;
  auto fits = [&](int64_t v) { return v >= lo && v <= hi; };
  return fits(std::min(in.x0, in.xmin)) && fits(std::max(in.x0, in.xmax)) && fits(in.y0) &&
         fits(std::max(in.y0, in.ymax + 1)) && !may_wrap(p, in);
}

// DdaDatapath for a triangle where nothing can wrap (exact_steps): the same
// registers with plain adds, and no wrap detector (exact() is pix()). Each
// register is then v0 + (X - x0) dX + (Y - y0) dY, so only what the state
// machine tests clock by clock is stepped: X, Y and the edges D1..D3. The
// outputs R..Z are worked out where a run starts (with_outputs()).
class ExactDatapath {
 public:
  static constexpr bool kExact = true;
  ExactDatapath(const Params& p, const DdaParams& in) : x0_(in.x0), y0_(in.y0) {
    pix_.x = in.x0;
    pix_.y = in.y0;
    for (int i = 0; i < kEpCount; ++i) {
      pix_.v[i] = v0_[i] = wrap(in.ep[i].v, DdaDatapath::format_of(p, i));
      right_[i] = in.ep[i].dx;
      left_[i] = -in.ep[i].dx;
      dy_[i] = in.ep[i].dy;
    }
    aux_ = live();
  }
  // The registers' steps to the right (s = +1) and to the left: kept both
  // ways, so that a step is adds only.
  const std::array<int64_t, kEpCount>& toward(int s) const { return s > 0 ? right_ : left_; }
  void step_x(int s) { step_x_by(s, 1); }
  // k steps of step_x(s) at once (the span path's jump along a run).
  void step_x_by(int s, int64_t k) {
    pix_.x += static_cast<int>(s * k);
    const std::array<int64_t, kEpCount>& d = toward(s);
    for (int i = kEpD1; i <= kEpD3; ++i) pix_.v[i] += k * d[i];
  }
  void step_y() {
    ++pix_.y;
    for (int i = kEpD1; i <= kEpD3; ++i) pix_.v[i] += dy_[i];
  }
  // X, Y and D1..D3 as they stand; R..Z as the last with_outputs() left them.
  const DdaRegisters& pix() const { return pix_; }
  const DdaRegisters& exact() const { return pix_; }
  // Every register as it stands.
  const DdaRegisters& with_outputs() {
    const int64_t dx = pix_.x - x0_, dy = pix_.y - y0_;
    for (int i = kEpR; i <= kEpZ; ++i) pix_.v[i] = v0_[i] + dx * right_[i] + dy * dy_[i];
    return pix_;
  }
  void save() { aux_ = live(); }
  void restore() {
    pix_.x = aux_.x;
    pix_.y = aux_.y;
    for (int e = 0; e < 3; ++e) pix_.v[kEpD1 + e] = aux_.d[e];
  }

 private:
  static_assert(kEpR == 0 && kEpZ == 4 && kEpD1 == 5 && kEpD3 == 7, "R..Z, then the edges");
  struct Live {  // the stepped registers
    int x, y;
    std::array<int64_t, 3> d;
  };
  Live live() const { return {pix_.x, pix_.y, {pix_.v[kEpD1], pix_.v[kEpD2], pix_.v[kEpD3]}}; }
  int x0_, y0_;
  DdaRegisters pix_;
  Live aux_;
  std::array<int64_t, kEpCount> v0_{}, right_{}, left_{}, dy_{};
};

// An output stage (fig. 4.20) does not carry the EP's integer part out as
// it is: clipped to 0..2^out_bits - 1, or cut to its low bits.
inline bool output_saturates(int64_t raw, const FixFormat& f) {
  return saturate_output(raw, f) != (raw >> f.frac_bits);
}

// A finished run's numerics from the wrapped uses and output clips counted
// clock by clock, and whether the triangle was affected (a wrapped value in
// use, or a value the preparer clamped).
inline EpNumerics run_numerics(const DdaParams& in, const std::array<uint64_t, kEpCount>& wraps,
                               const std::array<uint64_t, kEpCount>& saturations) {
  EpNumerics n;
  for (int i = 0; i < kEpCount; ++i) {
    n.ep[i].wraps = wraps[i];
    n.ep[i].saturations = saturations[i];
  }
  if (in.clamped || n.wraps() > 0) {
    n.triangles_affected = 1;
    n.first_affected_line = in.source_line;
  }
  return n;
}

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
