// The RTL DDA's size in yosys generic cells for a configuration's widths:
// the sweep's measured cost column beside the chip-count estimate
// (models/cost). The same synthesis as tools/hw_cost.sh's "whole DDA" row
// (synth -flatten, the wrap detector left out: a simulation aid), on the
// SystemVerilog package generated for the point (models/layout/rtl_package).
#pragma once

#include <optional>
#include <string>

#include "config/params.hpp"

namespace girtd {

bool yosys_available();
// Cell count, or nullopt when yosys is not installed or fails (its log is
// kept beside the cache). Results are cached in `cache_dir` by the values
// the DDA is elaborated with, so a sweep synthesises each width set once.
std::optional<long> dda_yosys_cells(const Params& p, const std::string& cache_dir);

}  // namespace girtd
