#include "dda/nf_unit.hpp"

#include "common/triangle_setup.hpp"

namespace girtd {

NormUnit::NormUnit(const FixFormat& d_format, int norm_frac_bits, double q)
    : q_zero_(q == 0), q_raw_(0), shift_(0), one_(1 << norm_frac_bits) {
  if (!q_zero_) {
    const int k = q_log2(q);
    q_raw_ = int64_t{1} << (d_format.frac_bits + k);
    shift_ = d_format.frac_bits + k - norm_frac_bits;
  }
}

int NormUnit::norm(int64_t d) const {
  if (d >= 0) return one_;
  if (!inside(d)) return 0;
  const int64_t x = d + q_raw_;  // 0 < x < Q
  return static_cast<int>(shift_ >= 0 ? (x >> shift_) : (x << -shift_));
}

NfRoute nf_route(int row) {
  switch (row & 15) {
    case 7: return NfRoute::kN1;
    case 11: return NfRoute::kN2;
    case 13: return NfRoute::kN3;
    case 14: return NfRoute::kT;
    case 15: return NfRoute::kOne;
    default: return NfRoute::kMultiply;
  }
}

int prom_product(int a, int b, int prom_frac_bits) {
  const int product = a * b;  // 2P fraction bits
  const int excess = 2 * prom_frac_bits - 8;
  return excess >= 0 ? (product >> excess) : (product << -excess);
}

int compute_nf(int n1, int n2, int n3, int t, int prom_frac_bits) {
  const int row = (n1 == kNfOne) << 3 | (n2 == kNfOne) << 2 | (n3 == kNfOne) << 1 | (t == kNfOne);
  switch (nf_route(row)) {
    case NfRoute::kOne: return kNfOne;
    case NfRoute::kN1: return n1;
    case NfRoute::kN2: return n2;
    case NfRoute::kN3: return n3;
    case NfRoute::kT: return t;
    case NfRoute::kMultiply: break;
  }
  const int cut = 8 - prom_frac_bits;  // 0.8 -> 1.P (operands are < 1 here)
  int acc = -1, product = 0;
  for (int v : {n1, n2, n3, t}) {
    if (v == kNfOne) continue;
    if (acc < 0) {
      acc = v >> cut;
      continue;
    }
    product = prom_product(acc, v >> cut, prom_frac_bits);
    acc = product >> cut;
  }
  return product;
}

}  // namespace girtd
