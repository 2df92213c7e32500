// Two's-complement fixed-point registers as the EPs hold them: `int_bits`
// integer bits (sign and guard bits included) and `frac_bits` fraction bits.
// Adders wrap like the hardware; outputs saturate or truncate as §4 says.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace girtd {

struct FixFormat {
  int int_bits = 0;
  int frac_bits = 0;
  int out_bits = 0;  // width of the unsigned output (0: no output, e.g. D)

  int total_bits() const { return int_bits + frac_bits; }
  // Output saturates only when there are guard bits above the output.
  bool saturates() const { return int_bits > out_bits; }
  int64_t one() const { return int64_t{1} << frac_bits; }
  int64_t raw_max() const { return (int64_t{1} << (total_bits() - 1)) - 1; }
  int64_t raw_min() const { return -(int64_t{1} << (total_bits() - 1)); }

  bool operator==(const FixFormat& o) const {
    return int_bits == o.int_bits && frac_bits == o.frac_bits && out_bits == o.out_bits;
  }
  bool operator!=(const FixFormat& o) const { return !(*this == o); }
};

// Sign-extends the low `bits` of v: what a `bits`-wide register holds.
inline int64_t wrap_to_bits(int64_t v, int bits) {
  const uint64_t mask = (bits >= 64) ? ~uint64_t{0} : ((uint64_t{1} << bits) - 1);
  uint64_t u = static_cast<uint64_t>(v) & mask;
  const uint64_t sign = uint64_t{1} << (bits - 1);
  return static_cast<int64_t>((u ^ sign) - sign);
}

inline int64_t wrap(int64_t v, const FixFormat& f) { return wrap_to_bits(v, f.total_bits()); }

// 2^n for 0 <= n < 63, exactly (std::ldexp's value; a per-triangle cost in the preparer).
inline double pow2(int n) { return static_cast<double>(int64_t{1} << n); }

// Float to fixed: symmetric rounding (half away from zero), saturated to the
// register range. `clamped` reports a saturation (the value did not fit).
inline int64_t to_fixed(double x, const FixFormat& f, bool* clamped = nullptr) {
  const double scaled = std::round(x * pow2(f.frac_bits));
  const double hi = static_cast<double>(f.raw_max());
  const double lo = static_cast<double>(f.raw_min());
  bool c = !(scaled >= lo && scaled <= hi);  // NaN counts as clamped
  if (clamped) *clamped = c;
  if (scaled > hi) return f.raw_max();
  if (scaled < lo || std::isnan(scaled)) return f.raw_min();
  return static_cast<int64_t>(scaled);
}

inline double to_double(int64_t raw, const FixFormat& f) {
  return std::ldexp(static_cast<double>(raw), -f.frac_bits);
}

// The EP output stage (fig. 4.20): the integer part, saturated to
// 0 .. 2^out_bits - 1 when guard bits exist, otherwise the low out_bits.
inline int saturate_output(int64_t raw, const FixFormat& f) {
  const int64_t integer = raw >> f.frac_bits;  // arithmetic shift: floor
  const int64_t top = (int64_t{1} << f.out_bits) - 1;
  if (!f.saturates()) return static_cast<int>(integer & top);
  if (integer < 0) return 0;
  if (integer > top) return static_cast<int>(top);
  return static_cast<int>(integer);
}

}  // namespace girtd
