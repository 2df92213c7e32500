// The one number parser (sim/io/number_text.hpp) against hand-worked cases.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "io/number_text.hpp"

namespace girtd {

TEST_CASE("integers: whole text, one leading +, int64 range", "[number_text]") {
  int64_t v = 0;
  CHECK(read_integer("42", v) == NumberRead::kOk);
  CHECK(v == 42);
  CHECK(read_integer("+7", v) == NumberRead::kOk);
  CHECK(v == 7);
  CHECK(read_integer("-9223372036854775808", v) == NumberRead::kOk);
  CHECK(v == INT64_MIN);
  CHECK(read_integer("9223372036854775808", v) == NumberRead::kOutOfRange);
  for (const char* bad : {"", "+", "-", "+-1", "++1", " 1", "1 ", "1.0", "0x10", "12ab"})
    CHECK(read_integer(bad, v) == NumberRead::kNotANumber);
}

TEST_CASE("reals: decimal only, out of range told apart by size", "[number_text]") {
  double v = 0;
  CHECK(read_real("1.5e3", v) == NumberRead::kOk);
  CHECK(v == 1500.0);
  CHECK(read_real("+.25", v) == NumberRead::kOk);
  CHECK(v == 0.25);
  CHECK(read_real("4.9e-324", v) == NumberRead::kOk);  // the smallest subnormal
  CHECK(v > 0);
  CHECK(read_real("1e-400", v) == NumberRead::kOutOfRange);
  CHECK((v == 0 && !std::signbit(v)));
  CHECK(read_real("-1e-400", v) == NumberRead::kOutOfRange);
  CHECK((v == 0 && std::signbit(v)));
  CHECK(read_real("1e999", v) == NumberRead::kOutOfRange);
  CHECK(v == HUGE_VAL);
  CHECK(read_real("-123.4e400", v) == NumberRead::kOutOfRange);
  CHECK(v == -HUGE_VAL);
  // An exponent past int64, and a tiny number written out in 400 zeros.
  CHECK(read_real("1e99999999999999999999", v) == NumberRead::kOutOfRange);
  CHECK(v == HUGE_VAL);
  CHECK(read_real("2e-99999999999999999999", v) == NumberRead::kOutOfRange);
  CHECK(v == 0);
  CHECK(read_real("0." + std::string(400, '0') + "1", v) == NumberRead::kOutOfRange);
  CHECK(v == 0);
  CHECK(read_real("1" + std::string(400, '0'), v) == NumberRead::kOutOfRange);
  CHECK(v == HUGE_VAL);
  CHECK(read_real("0.001e-400", v) == NumberRead::kOutOfRange);
  CHECK(v == 0);
  CHECK(read_real("nan", v) == NumberRead::kOk);
  CHECK(std::isnan(v));
  for (const char* bad : {"", "0x1p3", "1e5x", " 1", "1,5", "e5", "."}) CHECK(read_real(bad, v) == NumberRead::kNotANumber);
}

TEST_CASE("a leading real before a unit", "[number_text]") {
  double v = 0;
  size_t used = 0;
  CHECK(read_leading_real("200us", v, used) == NumberRead::kOk);
  CHECK(v == 200.0);
  CHECK(used == 3);
  CHECK(read_leading_real("+1.5ms", v, used) == NumberRead::kOk);
  CHECK(v == 1.5);
  CHECK(used == 4);
  CHECK(read_leading_real("us", v, used) == NumberRead::kNotANumber);
}

}  // namespace girtd
