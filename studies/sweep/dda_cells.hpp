// The RTL DDA's size in synthesised generic cells for a configuration's
// widths: the sweep's measured cost column (cost_yosys_dda_cells) beside the
// chip-count estimate (models/cost). The same synthesis as tools/hw_cost.sh's
// "whole DDA" row (synth -flatten, the wrap detector left out: a simulation
// aid), on the SystemVerilog package generated for the point
// (models/layout/rtl_package).
//
// The simulator runs no synthesis: `girtd --plan sweep` writes a request (a
// folder with the package and a synthesis script) for each width set not
// yet sized, the driver (tools/girtd) runs the synthesiser on it, and the
// sweep reads the count it left. Counts are cached by the values the DDA is
// elaborated with, so a sweep sizes each width set once.
#pragma once

#include <optional>
#include <string>

#include "config/params.hpp"

namespace girtd {

// The cell count, from the cache in `cache_dir` or from a request the driver
// has run (cached then); nullopt when neither is there or synthesis failed.
std::optional<long> dda_cells(const Params& p, const std::string& cache_dir);

// For a width set not yet sized: writes its request folder under `cache_dir`
// and returns it; nullopt when the count is known.
std::optional<std::string> dda_cells_request(const Params& p, const std::string& cache_dir);

}  // namespace girtd
