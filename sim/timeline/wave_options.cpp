#include "timeline/wave_options.hpp"

#include <cmath>

#include "common/input_error.hpp"
#include "io/number_text.hpp"

namespace girtd {
namespace {

constexpr double kMaxTimeNs = 1e15;

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

double parse_time(const std::string& text, double dda_clock_ns) {
  double v = 0;
  size_t used = 0;
  if (read_leading_real(text, v, used) != NumberRead::kOk || !std::isfinite(v) || v < 0)
    throw InputError("--wave-window", 0, "'" + text + "' is not a time (a number >= 0 with ns, us, ms, s or cycles)");
  const std::string unit = text.substr(used);
  double ns;
  if (unit.empty() || unit == "ns") ns = v;
  else if (unit == "us") ns = v * 1e3;
  else if (unit == "ms") ns = v * 1e6;
  else if (unit == "s") ns = v * 1e9;
  else if (unit == "cycles" || unit == "c") ns = v * dda_clock_ns;
  else throw InputError("--wave-window", 0, "unknown unit '" + unit + "' in '" + text + "' (ns, us, ms, s or cycles)");
  if (ns > kMaxTimeNs) throw InputError("--wave-window", 0, "'" + text + "' is beyond 10^15 ns");
  return ns;
}

}  // namespace

bool WaveOptions::vcd() const { return ends_with(path, ".vcd"); }

WaveOptions parse_wave_options(const std::string& path, const std::string& window,
                               const std::vector<std::string>& scopes, double dda_clock_ns, double base_tick_ns) {
  WaveOptions w;
  w.path = path;
  if (base_tick_ns < 2 || base_tick_ns != std::floor(base_tick_ns))
    throw InputError("--wave", 0, "waveforms need timing.base_tick_ns to be a whole number of ns, at least 2");
  if (!ends_with(path, ".fst") && !ends_with(path, ".vcd"))
    throw InputError("--wave", 0, "'" + path + "': the waveform file must end in .fst or .vcd");
  if (!window.empty()) {
    const size_t colon = window.find(':');
    if (colon == std::string::npos) throw InputError("--wave-window", 0, "expected T0:T1, got '" + window + "'");
    w.t0_ns = parse_time(window.substr(0, colon), dda_clock_ns);
    const std::string t1 = window.substr(colon + 1);
    if (!t1.empty()) w.t1_ns = parse_time(t1, dda_clock_ns);
    if (w.t1_ns <= w.t0_ns) throw InputError("--wave-window", 0, "T1 must be after T0 in '" + window + "'");
  }
  for (const std::string& s : scopes)
    if (s.empty() || s.find_first_of(" \t") != std::string::npos)
      throw InputError("--wave-scope", 0, "'" + s + "' is not a module path (e.g. TOP.girtd_backend.u_dda)");
  w.scopes = scopes;
  return w;
}

}  // namespace girtd
