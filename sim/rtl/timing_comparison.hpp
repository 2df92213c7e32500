// One trace through the two back-end timing engines — the Verilated RTL
// (hw/backend) and the timing model (sim/dda, sim/had) fed by the golden DDA and
// HAD — with their results and wall times side by side.
#pragma once

#include <optional>
#include <string>

#include "config/params.hpp"
#include "backends/model_series.hpp"
#include "rtl/backend_rtl.hpp"
#include "dda/dda_timing.hpp"

namespace girtd {

struct TimingComparison {
  BackendTiming model;
  BackendResult rtl;
  FifoSeries model_fifo, rtl_fifo;  // the DDA -> HAD FIFO's largest count per bin
  ScreenMaps model_maps;             // report.html's heat maps: from the golden DDA's pixels,
  std::optional<ScreenMaps> rtl_maps;  // and from the RTL's own pushes and counters
  double model_wall_s = 0;  // golden DDA + HAD + timing model (and its series)
  double rtl_wall_s = 0;    // the Verilated back end (and its heat maps)
};

TimingComparison compare_timing(const Params& p, const std::string& trace_path);

}  // namespace girtd
