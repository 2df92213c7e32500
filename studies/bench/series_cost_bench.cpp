#include "bench/series_cost_bench.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "bench/bench_stats.hpp"
#include "cli/child_render.hpp"
#include "engine/backend_registry.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

// Pairs of renders (with, without) per input and back end: the cost is a few
// per cent and this shared machine's noise about ten, so the ratio is taken
// pair by pair and its median quoted (approx renders in a tenth of a second).
int pairs_for(const BackendEntry& backend) { return backend.has(kRunsRtl) ? 11 : 21; }
// A trace the HAD bounds, with thousands of triangles; a model of twelve
// large ones.
const char* const kInputs[] = {"traces/demo.trace", "traces/models/cube.off"};

struct Timed {
  nlohmann::json report;
  double process_s = 0;
};

Timed render_timed(const std::string& input, const std::string& backend, const std::string& dir,
                   const ConfigFiles& config, bool series) {
  // Set only around the child: this process records no series of its own meanwhile.
  if (!series) setenv("GIRTD_NO_SERIES", "1", 1);
  const auto t0 = std::chrono::steady_clock::now();
  Timed t{render_in_child(input, backend, dir, config), 0};
  t.process_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  unsetenv("GIRTD_NO_SERIES");
  return t;
}

// The same run but for wall time and the page's charts.
bool same_run(nlohmann::json a, nlohmann::json b) {
  for (nlohmann::json* r : {&a, &b}) r->erase("wall_s");
  return a == b;
}

}  // namespace

SeriesCostBench run_series_cost_bench(const ConfigFiles& config, const std::string& out_dir) {
  SeriesCostBench b;
  const std::string dir = out_dir + "/series_cost";
  b.markdown =
      "\n## What report.html's series cost (pairs of renders, each in its own process)\n\n"
      "With: the stage timelines, the heat maps and the FIFOs' occupancy recorded, as every timed run does. "
      "Without: `GIRTD_NO_SERIES=1`. The two renders of a pair run one after the other (each first every other "
      "time); the cost is the median over the pairs of their ratio, the times the medians of each. `wall_s` "
      "covers the simulation, where the series are recorded (their memory is allocated and touched before it, "
      "with the rest of the model); the process time adds that, loading the input and writing frame.png, "
      "report.json and report.html (with the series, the page holds the charts and maps).\n\n"
      "| input | back end | pairs | wall s with | without | cost | process s with | without | cost | same report |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const char* input : kInputs) {
    for (const BackendEntry& entry : backend_registry()) {
      if (!entry.timed()) continue;
      const std::string& backend = entry.name;
      const std::string base = dir + "/" + fs::path(input).filename().string() + "-" + backend;
      std::vector<double> wall_on, wall_off, proc_on, proc_off, wall_ratio, proc_ratio;
      Timed on, off;
      const int pairs = pairs_for(entry);
      const bool ran = run_pairs(
          pairs,
          [&] {
            on = render_timed(input, backend, base + "-with", config, true);
            return !on.report.is_null() && on.report.at("wall_s").get<double>() > 0;
          },
          [&] {
            off = render_timed(input, backend, base + "-without", config, false);
            return !off.report.is_null() && off.report.at("wall_s").get<double>() > 0;
          },
          [&] {
            wall_on.push_back(on.report.at("wall_s"));
            wall_off.push_back(off.report.at("wall_s"));
            proc_on.push_back(on.process_s);
            proc_off.push_back(off.process_s);
            wall_ratio.push_back(wall_on.back() / wall_off.back());
            proc_ratio.push_back(proc_on.back() / proc_off.back());
          });
      if (!ran) {
        ++b.failures;
        b.markdown += std::string("| ") + input + " | " + backend + " | render failed |\n";
        continue;
      }
      const bool same = same_run(on.report, off.report);
      b.failures += !same;
      const double wn = median(wall_on), wf = median(wall_off), pn = median(proc_on), pf = median(proc_off);
      const double wall_cost = median(wall_ratio) - 1, proc_cost = median(proc_ratio) - 1;
      b.rows.push_back({{"input", input}, {"backend", backend}, {"pairs", pairs}, {"wall_s_with", wn}, {"wall_s_without", wf},
                        {"wall_cost", wall_cost}, {"process_s_with", pn}, {"process_s_without", pf},
                        {"process_cost", proc_cost}, {"same_report", same}});
      char line[512];
      std::snprintf(line, sizeof line, "| %s | %s | %d | %.3f | %.3f | %+.1f %% | %.3f | %.3f | %+.1f %% | %s |\n",
                    fs::path(input).filename().c_str(), backend.c_str(), pairs, wn, wf, 100 * wall_cost, pn, pf, 100 * proc_cost,
                    same ? "yes" : "NO");
      b.markdown += line;
      std::fputs(line, stdout);
      std::fflush(stdout);
    }
  }
  return b;
}

}  // namespace girtd
