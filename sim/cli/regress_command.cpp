// girtd regress: the RTL DDA against the golden model, trace by trace and on
// random triangles (sim/rtl/dda_regression). One row per trace, then
// "N passed, N failed"; exit 1 on any mismatch.
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/config_loader.hpp"
#include "rtl/backend_rtl.hpp"
#include "rtl/dda_regression.hpp"
#include "io/workload_list.hpp"

namespace girtd {

int run_regress(const RegressArgs& a) {
  Params p = load_params(a.config);
  std::vector<std::string> traces = a.traces;
  if (traces.empty() && a.random == 0) traces = sample_traces_at({TraceLevel::kTriangle, TraceLevel::kDda});
  int passed = 0, failed = 0;
  auto report = [&](const RegressionRow& r) {
    if (passed + failed == 0)  // the header once the RTL has been set up without complaint
      std::printf("%-44s %9s %10s %11s %9s %12s  %s\n", "trace", "triangles", "pixels", "DDA clocks", "stalls",
                  "back end us", "result");
    std::printf("%-44s %9llu %10llu %11llu %9llu %12.1f  %s\n", r.name.c_str(), (unsigned long long)r.triangles,
                (unsigned long long)r.pixels, (unsigned long long)r.clocks, (unsigned long long)r.stalls,
                double(r.ticks) * p.base_tick_ns * 1e-3, r.failure.empty() ? "pass" : "FAIL");
    if (!r.failure.empty()) std::printf("    first difference: %s\n", r.failure.c_str());
    std::fflush(stdout);
    (r.failure.empty() ? passed : failed)++;
  };
  const std::vector<bool> modes = a.both_compare_modes ? std::vector<bool>{false, true}
                                                       : std::vector<bool>{p.xy_compare_pipelined};
  for (bool pipelined : modes) {
    p.xy_compare_pipelined = pipelined;
    DdaRtl rtl(p);
    const std::unique_ptr<BackendRtl> backend = make_backend_rtl(p);
    BackendRtl* whole = a.dda_only ? nullptr : backend.get();
    for (const std::string& t : traces) report(regress_trace(t, p, rtl, whole, a.stall));
    if (a.random > 0) report(regress_random(a.random, a.seed, p, rtl, whole, a.stall));
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}

}  // namespace girtd
