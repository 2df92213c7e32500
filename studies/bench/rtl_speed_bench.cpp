#include "bench/rtl_speed_bench.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "bench/bench_stats.hpp"
#include "cli/child_render.hpp"
#include "io/trace_reader.hpp"
#include "dda/dda_rtl.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

constexpr int kRuns = 5;
constexpr double kTarget = 2e6;  // DDA clocks per wall second (issue: simulator speed)
const char* const kInputs[] = {"traces/models/cube.off", "traces/scenes/demo.json", "traces/demo.trace"};

// The Verilated DDA alone on every parameter set of a DDA-level trace:
// clocks and wall seconds (the receiver always ready).
std::pair<uint64_t, double> dda_alone(const Params& p, const std::string& dda_trace) {
  const Trace t = read_trace(dda_trace, std::nullopt, p);
  DdaRtl rtl(p);
  uint64_t clocks = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (const TraceFrame& f : t.frames)
    for (const DdaParams& d : f.dda) clocks += rtl.run(d, [](const DdaEmit&) {}).stats.cycles;
  return {clocks, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
}

}  // namespace

RtlSpeedBench run_rtl_speed_bench(const Params& params, const ConfigFiles& config, const std::string& out_dir) {
  RtlSpeedBench b;
  const std::string dir = out_dir + "/rtl_speed";
  fs::create_directories(dir);  // --dump writes into an existing folder
  b.markdown =
      "\n## The rtl back end's speed (DDA clocks per wall second, median of 5 renders)\n\n"
      "rtl: `render --backend rtl`, report.json's `dda_cycles` over `wall_s` (the whole back end: DDA, FIFO, "
      "HAD, cache, VRAM, every base tick it cannot skip). The ceiling: the Verilated DDA alone (`regress "
      "--dda-only`'s harness) on the same parameter sets, best of 3.\n\n"
      "| input | DDA clocks | rtl wall s | rtl clocks/s | DDA alone clocks/s | rtl / ceiling | >= 2e6 |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const char* input : kInputs) {
    const std::string base = dir + "/" + fs::path(input).filename().string();
    const std::string dump = base + ".dda";
    if (render_in_child(input, "golden", base + "-golden", config, {"--dump", "dda=" + dump}).is_null()) {
      ++b.failures;
      b.markdown += std::string("| ") + input + " | the golden dump failed |\n";
      continue;
    }
    double best_alone = 0;
    for (int i = 0; i < 3; ++i) {
      const auto [clocks, wall] = dda_alone(params, dump);
      if (wall > 0) best_alone = std::max(best_alone, double(clocks) / wall);
    }
    const auto [walls, r] = render_repeatedly(kRuns, input, "rtl", base + "-rtl", config);
    if (r.is_null()) {
      ++b.failures;
      b.markdown += std::string("| ") + input + " | render failed |\n";
      continue;
    }
    const double wall = median(walls), clocks = r.at("dda_cycles").get<double>();
    const double rate = wall > 0 ? clocks / wall : 0;
    b.rows.push_back({{"input", input}, {"dda_cycles", clocks}, {"rtl_wall_s", wall}, {"rtl_dda_clocks_per_s", rate},
                      {"dda_alone_clocks_per_s", best_alone}, {"meets_2e6", rate >= kTarget}});
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %.0f | %.3f | %.2e | %.2e | %.2f | %s |\n", fs::path(input).filename().c_str(),
                  clocks, wall, rate, best_alone, best_alone > 0 ? rate / best_alone : 0, rate >= kTarget ? "yes" : "no");
    b.markdown += line;
    std::fputs(line, stdout);
    std::fflush(stdout);
  }
  return b;
}

}  // namespace girtd
