// claims/ep_precision.hpp against the thesis' own error formula (§4.2.8):
// with the start value and the derivatives rounded to nearest, an EP's
// error after N steps is at most (1 + N) half-LSBs of its fraction, and
// random triangles come close to that worst case.
#include <catch2/catch.hpp>

#include <cmath>

#include "claims/ep_precision.hpp"

namespace girtd {
namespace {

double thesis_bound(int frac_bits, int steps) { return (1 + steps) * std::ldexp(1.0, -frac_bits - 1); }

TEST_CASE("EP error after N steps follows (1 + N) half-LSBs of the fraction", "[claims][precision]") {
  const Params thesis = Params::defaults();
  for (EpKind ep : kEpKinds)
    for (int delta : {-2, 0, 2})
      for (int steps : {1024, 2048}) {
        Params p = thesis;
        ep_format(p, ep).frac_bits += delta;
        const int f = ep_format(p, ep).frac_bits;
        const double e = ep_error_after_steps(p, ep, steps, 500);
        INFO("ep." << ep_key(ep) << ".frac_bits " << f << ", " << steps << " steps: " << e << " " << ep_unit(ep));
        CHECK(e <= thesis_bound(f, steps) * (1 + 1e-9));
        CHECK(e >= 0.9 * thesis_bound(f, steps));
      }
}

TEST_CASE("the fewest fraction bits: one more for twice the steps", "[claims][precision]") {
  const EpPrecision r = ep_precision(Params::defaults(), EpKind::kColor);
  // 9 bits: (1 + 1024) / 1024 = 1.001 LSB, within 1 LSB plus the start's half LSB (2^-10).
  CHECK(r.configured == 9);
  CHECK(r.fewest_across == 9);
  CHECK(r.fewest_corner == 10);
}

}  // namespace
}  // namespace girtd
