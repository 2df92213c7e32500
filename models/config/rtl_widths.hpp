// Widths of the RTL's run-time timing ports and its counters: design
// choices, and the limits params.cpp holds the timings to.
#pragma once

#include <cstdint>

namespace girtd {

inline constexpr int kRtlDdaPeriodBits = 8;   // dda.clock_ns, in base ticks
inline constexpr int kRtlTimeBits = 16;       // HAD access and blend, VRAM cycle
inline constexpr int kRtlLongTimeBits = 24;   // the frame clear, the steal period
inline constexpr int kRtlCountBits = 32;      // pixel and miss counters
inline constexpr int kRtlTickCountBits = 48;  // clock and tick counters
inline constexpr int kRtlQExponentBits = 4;   // Q = 2^k, k = -4..3 (signed), on the DDA's parameter port

inline constexpr int64_t max_of_bits(int bits) { return (int64_t{1} << bits) - 1; }

// ceil(log2(n)) for n >= 1: the bits that count 0 .. n - 1.
inline constexpr int bits_for(uint64_t n) {
  int b = 0;
  while ((uint64_t{1} << b) < n) ++b;
  return b;
}

}  // namespace girtd
