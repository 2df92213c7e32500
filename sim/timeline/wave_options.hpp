// render --wave FILE.fst|.vcd [--wave-window T0:T1] [--wave-scope NAME]...
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace girtd {

struct WaveOptions {
  std::string path;  // .fst, or .vcd (written as FST, then converted by fst2vcd)
  double t0_ns = 0;  // record ticks with t0 <= t <= t1
  double t1_ns = std::numeric_limits<double>::infinity();
  std::vector<std::string> scopes;  // module paths to record (e.g. TOP.girtd_backend.u_dda, pipeline.preparer); empty: all
  bool vcd() const;
};

// Times are numbers with a unit: ns (the default), us, ms, s, or cycles (DDA
// clocks of `dda_clock_ns`), at most 10^15 ns; T1 may be left empty (to the
// end). The base tick must be a whole number of ns, at least 2 (the clock is
// drawn low, then high, within it). Bad values are InputErrors naming the option.
WaveOptions parse_wave_options(const std::string& path, const std::string& window,
                               const std::vector<std::string>& scopes, double dda_clock_ns, double base_tick_ns);

}  // namespace girtd
