#include "cost/hardware_cost.hpp"

#include <cmath>

#include "config/built_stages.hpp"
#include "layout/rtl_layout.hpp"

namespace girtd {

namespace {

constexpr double kRegisterBitsPerChip = 8, kAdderBitsPerChip = 4;
constexpr double kFifoWordsPerChip = 64, kFifoBitsPerChip = 4;
constexpr double kVramBitsPerChip = 65536.0 * 4;
constexpr double kBoardFlopsPerS = 10e6, kChipsPerBoard = 60;
// The thesis' timings (config/girtd.json's defaults) are TTL's: faster needs
// ECL (the DDA clock; the HAD's access or its blend), at this factor.
constexpr double kEclFactor = 2;

double chips(double bits, double per_chip) { return std::ceil(bits / per_chip); }

}  // namespace

HardwareCost hardware_cost(const Params& p) {
  const RtlLayout l = rtl_layout(p);
  HardwareCost c;
  // EPs: R, G, B, T, Z, D1..D3, four registers and an adder each; X and Y
  // counters with value, AUX, min and max.
  const int ep_bits = 3 * p.ep_color.total_bits() + p.ep_t.total_bits() + p.ep_z.total_bits() + 3 * p.ep_d.total_bits();
  c.ep_register_bits = 4 * ep_bits + 2 * 4 * p.xy_bits;
  c.adder_bits = ep_bits + 2 * p.xy_bits;
  c.fifo_bits = p.fifo_max_depth * l.fifo.width;
  const int page_bits = l.page.pixels * l.vram.cell_bits;
  c.cache_bits = p.cache_pages * (page_bits + l.page.number_bits + 1);  // cells, tag, valid
  if (p.had_dirty_bits) c.cache_bits += p.cache_pages;
  if (p.had_write_behind) c.write_behind_bits = page_bits + l.page.number_bits + 1;
  if (p.had_prefetch) c.prefetch_bits = page_bits + l.page.number_bits + 2;
  const double frame_bits = double(p.screen_width) * p.screen_height * l.vram.width;  // two RGB buffers and Z
  c.vram_chips = int(std::max(chips(frame_bits, kVramBitsPerChip), chips(page_bits, 4)));
  for (const auto& [stage, rate] : p.stage_rate_flops_per_s)
    if (stage_built(p, stage)) c.front_end_boards += int(std::ceil(rate / kBoardFlopsPerS));
  static const Params thesis = Params::defaults();
  c.dda_clock_class = p.dda_clock_ns < thesis.dda_clock_ns ? "ECL" : "TTL";
  c.had_clock_class =
      p.had_access_ns < thesis.had_access_ns || p.had_blend_extra_ns < thesis.had_blend_extra_ns ? "ECL" : "TTL";
  const double dda_factor = c.dda_clock_class == "ECL" ? kEclFactor : 1, had_factor = c.had_clock_class == "ECL" ? kEclFactor : 1;
  c.dda_chips = dda_factor * (chips(c.ep_register_bits, kRegisterBitsPerChip) + chips(c.adder_bits, kAdderBitsPerChip));
  c.fifo_chips = std::ceil(p.fifo_max_depth / kFifoWordsPerChip) * chips(l.fifo.width, kFifoBitsPerChip);
  c.had_chips = had_factor * chips(c.cache_bits + c.write_behind_bits + c.prefetch_bits, kRegisterBitsPerChip);
  c.board_chips = kChipsPerBoard * c.front_end_boards;
  c.cost = c.dda_chips + c.fifo_chips + c.had_chips + c.vram_chips + c.board_chips;
  return c;
}

}  // namespace girtd
