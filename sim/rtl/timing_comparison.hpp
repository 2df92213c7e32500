// One trace through the two back ends that model the back end's time tick
// for tick — rtl (the Verilated hw/backend) and approx (the golden DDA and
// HAD, the timing model of sim/dda and sim/had) — with their results and
// wall times side by side, bare: no SystemC pipeline, no front end.
#pragma once

#include <optional>
#include <string>

#include "backends/modeled_time.hpp"
#include "config/params.hpp"

namespace girtd {

struct TimingComparison {
  BackendResult model, rtl;  // approx's and rtl's
  std::optional<FifoSeries> model_fifo, rtl_fifo;  // the DDA -> HAD FIFO's largest count per bin
  std::optional<ScreenMaps> model_maps, rtl_maps;  // report.html's heat maps
  double model_wall_s = 0;  // approx drawing the trace's frames (and its series)
  double rtl_wall_s = 0;    // rtl drawing them (and its heat maps)
};

// The series and maps are recorded unless GIRTD_NO_SERIES is set.
TimingComparison compare_timing(const Params& p, const std::string& trace_path);

}  // namespace girtd
