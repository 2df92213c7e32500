// models/cost/hardware_cost.hpp on the thesis' design, worked by hand from
// docs/design.md §4 and the weights the header states.
#include <catch2/catch.hpp>

#include "cost/hardware_cost.hpp"

namespace girtd {
namespace {

TEST_CASE("hardware cost of the thesis' design, by hand", "[cost]") {
  const HardwareCost c = hardware_cost(Params::defaults());
  // EPs: R, G, B, T 20 bits (11 + 9), Z 26 (18 + 8), D1..D3 24 (12 + 12):
  // 3 x 20 + 20 + 26 + 3 x 24 = 178 bits; four registers each, and X, Y
  // (16 bits) with four registers each: 4 x 178 + 8 x 16 = 840.
  CHECK(c.ep_register_bits == 840);
  CHECK(c.adder_bits == 178 + 2 * 16);
  // 840 / 8 = 105 register chips, 210 / 4 -> 53 adder chips; TTL at 35 ns.
  CHECK(c.dda_clock_class == "TTL");
  CHECK(c.dda_chips == 105 + 53);
  // One page of 16 cells of 40 bits (RGB + Z), a 16-bit page number
  // (20 address bits less 4), a valid bit: 657 bits -> 83 chips.
  CHECK(c.cache_bits == 16 * 40 + 16 + 1);
  CHECK(c.had_chips == 83);
  // Two RGB buffers and Z: 1 M x 64 bits / 256 Kbit = 256 VRAM chips.
  CHECK(c.vram_chips == 256);
  // Eight stages of 10 Mflop/s, one board each; no culling stage is built.
  CHECK(c.front_end_boards == 8);
  // The FIFO: 32 words of the 69-bit FIFO word, 64 x 4 bits a chip: 1 x 18.
  CHECK(c.fifo_chips == 18);
  // 158 + 18 + 83 + 256 + 480, as models/cost/README.md says.
  CHECK(c.cost == 995);
}

TEST_CASE("hardware cost: a stage is charged only when built", "[cost]") {
  const HardwareCost thesis = hardware_cost(Params::defaults());
  // Object culling, or back faces culled in every frame, builds the culling
  // stage: one more 10 Mflop/s board of 60 chips.
  for (const nlohmann::json& on : {nlohmann::json{{"objects", true}}, nlohmann::json{{"back_faces", "always"}}}) {
    const HardwareCost c = hardware_cost(Params::with_overrides({{"culling", on}}, "test"));
    CHECK(c.front_end_boards == 9);
    CHECK(c.cost == 995 + 60);
  }
  // The culling stage's rate costs nothing while it is not built ...
  const HardwareCost fast_off = hardware_cost(
      Params::with_overrides({{"pipeline", {{"flops_per_s", {{"culling", 40e6}}}}}}, "test"));
  CHECK(fast_off.cost == thesis.cost);
  // ... and its boards once it is: 40 Mflop/s is four.
  const HardwareCost fast_on = hardware_cost(Params::with_overrides(
      {{"culling", {{"objects", true}}}, {"pipeline", {{"flops_per_s", {{"culling", 40e6}}}}}}, "test"));
  CHECK(fast_on.cost == 995 + 4 * 60);
}

TEST_CASE("hardware cost: write-behind adds a page register, ECL doubles the DDA", "[cost]") {
  const Params base = Params::defaults();
  const HardwareCost b = hardware_cost(base);
  const HardwareCost wb = hardware_cost(Params::with_overrides({{"had", {{"write_behind", true}}}}, "test"));
  CHECK(wb.write_behind_bits == 16 * 40 + 16 + 1);
  CHECK(wb.had_chips > b.had_chips);
  const HardwareCost ecl = hardware_cost(Params::with_overrides({{"dda", {{"clock_ns", 25.0}}}}, "test"));
  CHECK(ecl.dda_clock_class == "ECL");
  CHECK(ecl.dda_chips == 2 * b.dda_chips);
  // A blend faster than the thesis' 50 ns more makes the HAD ECL, like a faster access.
  const HardwareCost blend = hardware_cost(Params::with_overrides({{"had", {{"blend_extra_ns", 25.0}}}}, "test"));
  CHECK(blend.had_clock_class == "ECL");
  CHECK(blend.had_chips == 2 * b.had_chips);
}

}  // namespace
}  // namespace girtd
