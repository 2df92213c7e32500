// Norm_Q, the U decoder and the PROM products, against values worked by hand
// from §4.2.5 - 4.2.7 (1.8 fixed point: 256 = 1.0; D has 12 fraction bits).
#include <catch2/catch.hpp>

#include "dda/nf_unit.hpp"

namespace girtd {

TEST_CASE("Norm with Q = 0 is a step at D = 0", "[nf]") {
  const Params p = Params::defaults();
  const NormUnit n(p.ep_d, 8, 0.0);
  CHECK(n.inside(0));
  CHECK(n.norm(0) == 256);
  CHECK_FALSE(n.inside(-1));  // -1/4096 px outside
  CHECK(n.norm(-1) == 0);
}

TEST_CASE("Norm with Q = 1: 1 + D in the fringe, truncated to 8 fraction bits", "[nf]") {
  const Params p = Params::defaults();
  const NormUnit n(p.ep_d, 8, 1.0);
  CHECK(n.norm(4096) == 256);   // D = +1
  CHECK(n.norm(-2048) == 128);  // D = -0.5: (4096 - 2048) >> 4 = 128
  CHECK(n.norm(-1) == 255);     // 4095 >> 4 = 255
  CHECK(n.inside(-4095));       // D > -1: inside, although
  CHECK(n.norm(-4095) == 0);    // 1 >> 4 truncates to 0
  CHECK_FALSE(n.inside(-4096)); // D = -1: Norm = 0, outside
}

TEST_CASE("Norm with Q = 2 and Q = 1/2 scales the fringe", "[nf]") {
  const Params p = Params::defaults();
  const NormUnit wide(p.ep_d, 8, 2.0);
  CHECK(wide.norm(-4096) == 128);  // 1 + (-1)/2 = 0.5: (8192 - 4096) >> 5
  CHECK(wide.inside(-8191));
  CHECK_FALSE(wide.inside(-8192));
  const NormUnit sharp(p.ep_d, 8, 0.5);
  CHECK(sharp.norm(-1024) == 128);  // 1 + (-0.25)/0.5 = 0.5: (2048 - 1024) >> 3
  CHECK_FALSE(sharp.inside(-2048));
}

TEST_CASE("U decoder: all 16 rows of the thesis' routing table (4.2.7)", "[nf]") {
  // Row = n1=1 n2=1 n3=1 T=1 as bits 3..0; the table as printed in the thesis.
  const NfRoute table[16] = {
      NfRoute::kMultiply, NfRoute::kMultiply, NfRoute::kMultiply, NfRoute::kMultiply,  // 0-3
      NfRoute::kMultiply, NfRoute::kMultiply, NfRoute::kMultiply, NfRoute::kN1,        // 4-7
      NfRoute::kMultiply, NfRoute::kMultiply, NfRoute::kMultiply, NfRoute::kN2,        // 8-11
      NfRoute::kMultiply, NfRoute::kN3,       NfRoute::kT,        NfRoute::kOne,       // 12-15
  };
  for (int row = 0; row < 16; ++row) {
    INFO("row " << row);
    CHECK(nf_route(row) == table[row]);
  }
}

TEST_CASE("nf for U = 0 and U = 1 passes the one value unchanged", "[nf]") {
  CHECK(compute_nf(256, 256, 256, 256, 4) == 256);
  CHECK(compute_nf(77, 256, 256, 256, 4) == 77);    // row 7: n1
  CHECK(compute_nf(256, 201, 256, 256, 4) == 201);  // row 11: n2
  CHECK(compute_nf(256, 256, 13, 256, 4) == 13);    // row 13: n3
  CHECK(compute_nf(256, 256, 256, 99, 4) == 99);    // row 14: T
}

TEST_CASE("nf for U >= 2 goes through 1.4 operands and 8-bit products", "[nf]") {
  // n1 = 0.5 (128), T = 0.75 (192): 1.4 operands 8 and 12, product 96 = 0.375.
  CHECK(compute_nf(128, 256, 256, 192, 4) == 96);
  // n1 = n2 = 0.5: 8 x 8 = 64 (0.25); cut to 1.4: 4; x n3 = 200 -> 12: 48.
  CHECK(compute_nf(128, 128, 200, 256, 4) == 48);
  // Four factors: 0.5^4 with exact 1.4 operands: 8x8 = 64 -> 4; 4x8 = 32 -> 2; 2x8 = 16.
  CHECK(compute_nf(128, 128, 128, 128, 4) == 16);
  // Operands below 1/16 vanish in 1.4: 15 -> 0.
  CHECK(compute_nf(15, 255, 256, 256, 4) == 0);
}

TEST_CASE("T = 255 at the EP output means exactly 1.0", "[nf]") {
  CHECK(t_operand(255) == 256);
  CHECK(t_operand(254) == 254);
  CHECK(t_operand(0) == 0);
}

}  // namespace girtd
