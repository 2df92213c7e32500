// Unit tests for models/common/fixed_point.hpp: register wrap, float-to-fixed
// rounding and saturation, and the EP output stage. Every expectation is
// worked out by hand in the comment next to it.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "common/fixed_point.hpp"

namespace girtd {
namespace {

// The thesis formats (config/girtd.json), written out here on purpose.
const FixFormat kColor{11, 9, 8};  // 20 bits, LSB = 1/512, out 8 bits, 3 guard bits
const FixFormat kD{12, 12, 0};     // 24 bits, LSB = 1/4096

}  // namespace

TEST_CASE("FixFormat derived quantities for the colour and D formats", "[fixed]") {
  // colour 11.9: 20 bits; one = 2^9 = 512; max = 2^19 - 1 = 524287; min = -2^19 = -524288.
  CHECK(kColor.total_bits() == 20);
  CHECK(kColor.one() == 512);
  CHECK(kColor.raw_max() == 524287);
  CHECK(kColor.raw_min() == -524288);
  CHECK(kColor.saturates());  // 11 integer bits > 8 output bits: guard bits exist
  // D 12.12: 24 bits; one = 4096; max = 2^23 - 1 = 8388607.
  CHECK(kD.total_bits() == 24);
  CHECK(kD.one() == 4096);
  CHECK(kD.raw_max() == 8388607);
  CHECK(kD.raw_min() == -8388608);
  // A format whose integer part is exactly the output width has no guard bits.
  CHECK_FALSE(FixFormat{8, 4, 8}.saturates());
  CHECK(FixFormat{8, 4, 8} == FixFormat{8, 4, 8});
  CHECK(FixFormat{8, 4, 8} != FixFormat{8, 5, 8});
}

TEST_CASE("wrap_to_bits sign-extends like a two's-complement register", "[fixed]") {
  // 0x7FFFFF is the largest 24-bit value; +1 = 0x800000 has the sign bit set:
  // as a 24-bit register it reads -2^23 = -0x800000.
  CHECK(wrap_to_bits(0x7FFFFF, 24) == 0x7FFFFF);
  CHECK(wrap_to_bits(0x7FFFFF + 1, 24) == -0x800000);
  // 0xFFFFFF: all 24 bits set = -1.
  CHECK(wrap_to_bits(0xFFFFFF, 24) == -1);
  // -1 stays -1; -0x800000 - 1 wraps to +0x7FFFFF.
  CHECK(wrap_to_bits(-1, 24) == -1);
  CHECK(wrap_to_bits(-0x800000 - 1, 24) == 0x7FFFFF);
  // Bits above the register are thrown away: 0x1000005 -> low 24 bits = 5.
  CHECK(wrap_to_bits(0x1000005, 24) == 5);
  // 8 bits: 200 = 0xC8 -> 200 - 256 = -56.
  CHECK(wrap_to_bits(200, 8) == -56);
  // 64 bits is the identity.
  CHECK(wrap_to_bits(std::numeric_limits<int64_t>::min(), 64) == std::numeric_limits<int64_t>::min());
  // wrap() uses the format's total width: colour is 20 bits, 2^19 -> -2^19.
  CHECK(wrap(524288, kColor) == -524288);
  CHECK(wrap(524287, kColor) == 524287);
}

TEST_CASE("to_fixed rounds half an LSB away from zero for both signs", "[fixed]") {
  bool clamped = true;
  // 1.25 * 512 = 640 exactly.
  CHECK(to_fixed(1.25, kColor, &clamped) == 640);
  CHECK_FALSE(clamped);
  // 0.5 LSB = 0.5/512: scaled 0.5 -> 1 (away from zero), -0.5 -> -1.
  CHECK(to_fixed(0.5 / 512, kColor) == 1);
  CHECK(to_fixed(-0.5 / 512, kColor) == -1);
  // 2.5 LSB -> 3 and -3 (symmetric, not round-half-even which would give 2).
  CHECK(to_fixed(2.5 / 512, kColor) == 3);
  CHECK(to_fixed(-2.5 / 512, kColor) == -3);
  // Just under half an LSB rounds to zero: 0.49 LSB -> 0, -0.49 LSB -> 0.
  CHECK(to_fixed(0.49 / 512, kColor) == 0);
  CHECK(to_fixed(-0.49 / 512, kColor) == 0);
  // 1.4 LSB -> 1, 1.6 LSB -> 2, -1.6 LSB -> -2.
  CHECK(to_fixed(1.4 / 512, kColor) == 1);
  CHECK(to_fixed(1.6 / 512, kColor) == 2);
  CHECK(to_fixed(-1.6 / 512, kColor) == -2);
  // D 12.12: 0.1 * 4096 = 409.6 -> 410; -0.1 -> -410.
  CHECK(to_fixed(0.1, kD) == 410);
  CHECK(to_fixed(-0.1, kD) == -410);
  // to_double inverts exact values: 640 / 512 = 1.25; -410 / 4096 = -0.10009765625.
  CHECK(to_double(640, kColor) == 1.25);
  CHECK(to_double(-410, kD) == -0.10009765625);
}

TEST_CASE("to_fixed saturates out-of-range values and reports clamped", "[fixed]") {
  bool clamped = false;
  // Largest colour value: 524287 / 512 = 1023.998046875 fits exactly.
  CHECK(to_fixed(1023.998046875, kColor, &clamped) == 524287);
  CHECK_FALSE(clamped);
  // 1024.0 -> 524288 = raw_max + 1: saturates to raw_max.
  CHECK(to_fixed(1024.0, kColor, &clamped) == 524287);
  CHECK(clamped);
  // -1024.0 -> -524288 = raw_min exactly: fits, not clamped.
  CHECK(to_fixed(-1024.0, kColor, &clamped) == -524288);
  CHECK_FALSE(clamped);
  // -1024 - 1 LSB -> -524289 < raw_min: clamps to raw_min.
  CHECK(to_fixed(-1024.0 - 1.0 / 512, kColor, &clamped) == -524288);
  CHECK(clamped);
  // A huge value saturates; D max = 8388607 (2047.999755859375).
  CHECK(to_fixed(1e30, kD, &clamped) == 8388607);
  CHECK(clamped);
  CHECK(to_fixed(-1e30, kD, &clamped) == -8388608);
  CHECK(clamped);
  // Infinities clamp to the matching end.
  CHECK(to_fixed(std::numeric_limits<double>::infinity(), kColor, &clamped) == 524287);
  CHECK(clamped);
  CHECK(to_fixed(-std::numeric_limits<double>::infinity(), kColor, &clamped) == -524288);
  CHECK(clamped);
  // The flag is optional.
  CHECK(to_fixed(5000.0, kColor) == 524287);
}

TEST_CASE("to_fixed treats NaN as clamped and returns a value inside the register", "[fixed]") {
  bool clamped = false;
  const int64_t v = to_fixed(std::numeric_limits<double>::quiet_NaN(), kColor, &clamped);
  CHECK(clamped);
  CHECK(v >= kColor.raw_min());
  CHECK(v <= kColor.raw_max());
}

TEST_CASE("saturate_output with guard bits clamps to 0..255 and truncates", "[fixed]") {
  // Negative values give 0: -0.5 -> raw -256, integer part floor(-0.5) = -1 -> 0.
  CHECK(saturate_output(to_fixed(-0.5, kColor), kColor) == 0);
  CHECK(saturate_output(to_fixed(-1000.0, kColor), kColor) == 0);
  // -1 LSB: floor(-1/512) = -1 -> 0 (not 255).
  CHECK(saturate_output(-1, kColor) == 0);
  // 256.25 -> integer 256 > 255 -> 255; 1000.7 -> 255.
  CHECK(saturate_output(to_fixed(256.25, kColor), kColor) == 255);
  CHECK(saturate_output(to_fixed(1000.7, kColor), kColor) == 255);
  // 17.99 -> raw round(9210.88) = 9211; 9211 >> 9 = 17 (truncation, not rounding).
  CHECK(to_fixed(17.99, kColor) == 9211);
  CHECK(saturate_output(9211, kColor) == 17);
  // 255.998 -> raw round(131070.98) = 131071 -> 131071 >> 9 = 255.
  CHECK(saturate_output(to_fixed(255.998, kColor), kColor) == 255);
  // 0 -> 0, 1.0 -> 1, 128.5 -> 128.
  CHECK(saturate_output(0, kColor) == 0);
  CHECK(saturate_output(512, kColor) == 1);
  CHECK(saturate_output(to_fixed(128.5, kColor), kColor) == 128);
  // Z 18.8 out 16: 70000.0 -> 65535; 1234.9 -> 1234.
  const FixFormat z{18, 8, 16};
  CHECK(saturate_output(to_fixed(70000.0, z), z) == 65535);
  CHECK(saturate_output(to_fixed(1234.9, z), z) == 1234);
}

TEST_CASE("saturate_output without guard bits keeps the low output bits", "[fixed]") {
  const FixFormat f{8, 4, 8};  // 8 integer bits = 8 output bits: no saturation
  // 127.0 = raw 127 * 16 = 2032 -> 127.
  CHECK(saturate_output(2032, f) == 127);
  // -1.0 = raw -16 -> integer -1 = ...11111111 -> low 8 bits = 255 (wraps, not 0).
  CHECK(saturate_output(-16, f) == 255);
  // -128.0 = raw -2048 -> integer -128 -> low 8 bits 0x80 = 128.
  CHECK(saturate_output(-2048, f) == 128);
  // 300.5 (outside the register, but the stage only looks at bits):
  // raw 300.5 * 16 = 4808 -> integer 300 = 0x12C -> low 8 bits 0x2C = 44.
  CHECK(saturate_output(4808, f) == 44);
  // -0.5 = raw -8 -> floor -> -1 -> 255.
  CHECK(saturate_output(-8, f) == 255);
}

}  // namespace girtd
