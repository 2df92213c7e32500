// A hardware cost model for design-space sweeps (`girtd sweep`): what a
// configuration would cost to build in 1988 parts, computed from the config
// alone. Each component is counted in its own unit and converted to chips;
// `cost` is their weighted sum, an estimate of the chip count, and defines
// "cheapest" in the sweeps. The weights are assumptions, stated here and in
// models/cost/README.md, not measurements:
// - registers and the cache: 8 bits per chip (an octal flip-flop, 74F374);
// - adders: 4 bits per chip (74F283); EP adders and the X, Y counters;
// - the DDA -> HAD FIFO: 64 words x 4 bits per chip (74F433-class), built
//   fifo.max_depth deep;
// - VRAM: 64K x 4 parts, enough for two RGB frame buffers and Z (256 chips)
//   and at least as many as one page access reads in parallel (cell bits / 4
//   per pixel of the page);
// - the write-behind register and the prefetch buffer: a page of cells and
//   its page number each, in registers;
// - front-end boards: each built stage (config/built_stages.hpp: the culling
//   stage only when the config turns culling on) is a board per 10 Mflop/s
//   of its rate (the thesis' boards), rounded up, 60 chips each;
// - clock class: a DDA clock under 35 ns or a HAD access under 25 ns needs
//   ECL for that unit (the thesis' TTL limits): its chips count twice.
#pragma once

#include <string>
#include <vector>

#include "config/params.hpp"

namespace girtd {

struct HardwareCost {
  int ep_register_bits = 0;  // EP value, d/dx, d/dy, AUX registers; X, Y value, AUX, min, max
  int adder_bits = 0;
  int fifo_bits = 0;         // DDA -> HAD FIFO as built
  int cache_bits = 0;
  int write_behind_bits = 0, prefetch_bits = 0;
  int vram_chips = 0;
  int front_end_boards = 0;
  std::string dda_clock_class, had_clock_class;  // "TTL" or "ECL"
  // Chips by component and in all (the weighted sum).
  double dda_chips = 0, fifo_chips = 0, had_chips = 0, board_chips = 0;
  double cost = 0;
};

HardwareCost hardware_cost(const Params& p);

}  // namespace girtd
