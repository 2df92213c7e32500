// Coverage and final transparency (§4.2.5 - 4.2.7): Norm_Q from a D register,
// the U decoder's routing table, and nf through the 5-bit product PROMs.
// Values are 1.8 fixed point (256 = 1.0) unless said otherwise.
#pragma once

#include <array>
#include <cstdint>

#include "config/params.hpp"

namespace girtd {

// Norm_Q for Q = 2^k (or 0) on a raw D register: inside <=> D > -Q (Q > 0)
// or D >= 0 (Q = 0); the fringe value is (D + Q) scaled to 1.8 by a right
// shift, truncating.
class NormUnit {
 public:
  NormUnit(const FixFormat& d_format, int norm_frac_bits, double q);
  bool inside(int64_t d) const { return d >= lowest_inside(); }
  int64_t lowest_inside() const { return q_zero_ ? 0 : 1 - q_raw_; }
  int norm(int64_t d) const;  // 0..256
  int64_t q_raw() const { return q_raw_; }

 private:
  bool q_zero_;
  int64_t q_raw_;
  int shift_;  // right shift of D + Q onto norm_frac_bits (negative: left)
  int one_;
};

// What the U decoder routes to nf (the table of §4.2.7).
enum class NfRoute { kMultiply, kN1, kN2, kN3, kT, kOne };

// Row index as in the thesis: bit 3 = (n1 == 1), bit 2 = (n2 == 1),
// bit 1 = (n3 == 1), bit 0 = (T == 1).
NfRoute nf_route(int row);

// T's 8-bit output as an nf operand: 255 means exactly 1.0, else 0.T8.
inline int t_operand(int t8) { return t8 >= 255 ? 256 : t8; }

// nf = n1 n2 n3 T through the decoder: U <= 1 passes the one non-1 value;
// U >= 2 cuts each non-1 operand to 1.P (P = prom_frac_bits) and multiplies
// pairwise through the PROM table, cutting each 8-bit product back to 1.P
// before the next; the last product is nf's fraction.
int compute_nf(int n1, int n2, int n3, int t, int prom_frac_bits);

// One PROM: two 1.P operands in, 8-bit 0.8 product out.
int prom_product(int a, int b, int prom_frac_bits);

}  // namespace girtd
