// Numbers in text, one parser for every reader (traces, model checks, JSON
// pointers, the command line's times): std::from_chars, so locale-free, no
// hexadecimal, no leading blanks. The whole of the text must be the number;
// one leading '+' is allowed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace girtd {

enum class NumberRead { kOk, kNotANumber, kOutOfRange };

// kOutOfRange: the value does not fit an int64_t.
NumberRead read_integer(std::string_view text, int64_t& value);

// "nan" and "inf" read as such. kOutOfRange: beyond double's range, with
// `value` the infinity of the text's sign, or below its smallest subnormal,
// with `value` a zero of that sign.
NumberRead read_real(std::string_view text, double& value);

// The real number at the start of `text` (a number then a unit): its length
// in `used`.
NumberRead read_leading_real(std::string_view text, double& value, size_t& used);

}  // namespace girtd
