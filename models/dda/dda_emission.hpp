// What the DDA makes of its registers at one pixel, for one triangle: the
// edge tests (Norm units, §4.2.5), the pixel it emits (output stages of
// fig. 4.20 and nf, §4.2.7) and whether an output clipped. Shared by the
// clocked path and the span path of the state machine.
#pragma once

#include <algorithm>
#include <array>

#include "common/fixed_point.hpp"
#include "config/params.hpp"
#include "dda/dda_datapath.hpp"
#include "dda/dda_engine.hpp"
#include "dda/nf_unit.hpp"

namespace girtd {

inline constexpr std::array<int, 5> kOutputEps = {kEpR, kEpG, kEpB, kEpT, kEpZ};

class DdaEmission {
 public:
  DdaEmission(const Params& p, const DdaParams& in)
      : params_(p),
        in_(in),
        // One Norm unit per edge: an interior edge's (edge flags) has no fringe.
        norm_{unit(p, in, 0), unit(p, in, 1), unit(p, in, 2)} {
    for (int i = 0; i < kEpCount; ++i) format_[i] = &DdaDatapath::format_of(p, i);
    if (in.q > 0) soft_edges_ = ~in.hard_edges & 7;
    for (int e = 0; e < 3; ++e) lowest_inside_[e] = norm_[e].lowest_inside();
    // The raw values an output stage passes unchanged (T: and its 1.0, one past the top, when it saturates).
    for (int i : kOutputEps) {
      const FixFormat& f = *format_[i];
      const int64_t past_top = (int64_t{1} << f.out_bits) + (i == kEpT && f.saturates() ? 1 : 0);
      plain_hi_[i] = (past_top << f.frac_bits) - 1;
    }
    plain_format_ = {format_[kEpR]->frac_bits, format_[kEpZ]->frac_bits, format_[kEpT]->frac_bits,
                     (int64_t{1} << format_[kEpT]->out_bits) - 1, soft_edges_};
  }

  const NormUnit& norm(int edge) const { return norm_[edge]; }
  // The Norm unit's inside test: D at least the lowest inside value (NormUnit::inside).
  int64_t lowest_inside(int ep) const { return lowest_inside_[ep - kEpD1]; }
  bool edge_inside(const DdaRegisters& r, int ep) const { return r.v[ep] >= lowest_inside(ep); }
  bool d_inside(const DdaRegisters& r) const {
    return edge_inside(r, kEpD1) && edge_inside(r, kEpD2) && edge_inside(r, kEpD3);
  }
  const FixFormat& format(int ep) const { return *format_[ep]; }

  // An output stage clipped this value (counted per pixel emitted). T's 1.0
  // is 256, carried out as 255 by design (models/dda/README.md): not a clip.
  bool counts_saturation(int ep, int64_t raw) const {
    const FixFormat& f = *format_[ep];
    const bool t_one = ep == kEpT && (raw >> f.frac_bits) == 256;
    return !t_one && output_saturates(raw, f);
  }

  DdaEmit emit(const DdaRegisters& r, uint64_t cycle) const {
    DdaEmit e;
    e.raw = r.v;
    e.cycle = cycle;
    const int t = t_operand(saturate_output(r.v[kEpT], params_.ep_t));
    const int n1 = norm_[0].norm(r.v[kEpD1]), n2 = norm_[1].norm(r.v[kEpD2]), n3 = norm_[2].norm(r.v[kEpD3]);
    e.pixel = output_pixel(r, params_, compute_nf(n1, n2, n3, t, params_.prom_frac_bits));
    // Covered: inside every hard edge, strictly inside every soft one (a
    // pixel on a silhouette is on the boundary, not a triangle's own).
    e.covered = n1 == kNfOne && n2 == kNfOne && n3 == kNfOne;
    for (int i = 0; i < 3; ++i)
      if (in_.q > 0 && !((in_.hard_edges >> i) & 1) && r.v[kEpD1 + i] == 0) e.covered = false;
    return e;
  }

  // Whether emit() reduces to shifts on every pixel of a span of k + 1
  // pixels from registers v by `step` (v inside): no output clips, and
  // every edge with a fringe has D >= 0 (the others do, being inside), so
  // each Norm is 1 and nf is T (§4.2.7). Each part holds on an interval of
  // a register's values, so where it holds at both ends of a linear
  // register, it holds all along.
  bool plain_span(const std::array<int64_t, kEpCount>& v, const std::array<int64_t, kEpCount>& step, int64_t k) const {
    static_assert(kEpR == 0 && kEpZ == 4, "the outputs are EPs 0..4");
    // Unsigned, 0 <= x <= hi is one compare.
    auto within = [](int64_t x, int64_t hi) { return static_cast<uint64_t>(x) <= static_cast<uint64_t>(hi); };
    for (int i = kEpR; i <= kEpZ; ++i)
      if (!within(v[i], plain_hi_[i]) || !within(v[i] + k * step[i], plain_hi_[i])) return false;
    for (int e = 0; e < 3 && soft_edges_; ++e)
      if (((soft_edges_ >> e) & 1) && (v[kEpD1 + e] < 0 || v[kEpD1 + e] + k * step[kEpD1 + e] < 0)) return false;
    return true;
  }
  // What emit_plain needs, by value: a copy the compiler can keep in
  // registers while the sink writes memory. Its three parts of a plain
  // pixel serve emit_plain and the span path's PlainRun alike.
  struct PlainFormat {
    int colour_frac, z_frac, t_frac;  // R, G and B share one format (ep.color)
    int64_t t_top;
    unsigned soft_edges;

    // X, Y, R, G, B and Z from the registers R..Z at v (nf left 0).
    Pixel outputs(int x, int y, const int64_t* v) const {
      Pixel p;
      p.x = x;
      p.y = y;
      p.r = static_cast<uint8_t>(v[kEpR] >> colour_frac);
      p.g = static_cast<uint8_t>(v[kEpG] >> colour_frac);
      p.b = static_cast<uint8_t>(v[kEpB] >> colour_frac);
      p.z = static_cast<uint16_t>(v[kEpZ] >> z_frac);
      return p;
    }
    // nf: T, its 1.0 carried out as 255 (t_operand).
    uint16_t nf(int64_t t) const {
      return static_cast<uint16_t>(t_operand(static_cast<int>(std::min(t >> t_frac, t_top))));
    }
    // Covered unless on a soft edge (D = 0), from D1..D3 at d.
    bool covered(const int64_t* d) const {
      return !(((soft_edges & 1) && d[0] == 0) || ((soft_edges & 2) && d[1] == 0) || ((soft_edges & 4) && d[2] == 0));
    }
  };
  const PlainFormat& plain_format() const { return plain_format_; }
  // emit() where plain_span holds.
  static DdaEmit emit_plain(const PlainFormat& f, const DdaRegisters& r, uint64_t cycle) {
    DdaEmit e;
    e.raw = r.v;
    e.cycle = cycle;
    e.pixel = f.outputs(r.x, r.y, r.v.data());
    e.pixel.nf = f.nf(r.v[kEpT]);
    e.covered = f.covered(&r.v[kEpD1]);
    return e;
  }

 private:
  static NormUnit unit(const Params& p, const DdaParams& in, int edge) {
    return NormUnit(p.ep_d, p.norm_frac_bits, (in.hard_edges >> edge) & 1 ? 0.0 : in.q);
  }
  const Params& params_;
  const DdaParams& in_;
  std::array<NormUnit, 3> norm_;
  std::array<const FixFormat*, kEpCount> format_{};
  std::array<int64_t, 3> lowest_inside_{};
  std::array<int64_t, kEpCount> plain_hi_{};  // plain_span(): each output's values run 0 .. this
  unsigned soft_edges_ = 0;  // bit i: D(i+1) has a fringe (Q > 0, not a hard edge): 0 is on its boundary
  PlainFormat plain_format_{};
};

}  // namespace girtd
