#include "bench/pipeline_bench.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <vector>

#include "io/subprocess.hpp"
#include "io/trace_reader.hpp"
#include "io/workload_list.hpp"
#include "cli/child_render.hpp"
#include "bench/expectations.hpp"
#include "io/sha256.hpp"
#include "rtl/timing_comparison.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

bool same_counts(const nlohmann::json& a, const nlohmann::json& b) {
  for (const char* k : {"triangles_in", "triangles_drawn", "pixels_generated", "pixels_written", "pixels_blended",
                        "pixels_z_rejected", "pixels_dropped", "dda_cycles", "dda_states", "image_sha256"})
    if (a.value(k, nlohmann::json()) != b.value(k, nlohmann::json())) return false;
  // The HAD's busy ticks and the cache's page misses, which the timing model
  // gets exactly.
  return a.at("stages").at("had").at("busy_s") == b.at("stages").at("had").at("busy_s") &&
         a.at("cache") == b.at("cache");
}

// Each back end's report against the stored record: "golden: key: ..." lines.
std::vector<std::string> differences_from(const nlohmann::json& stored,
                                          const std::vector<std::pair<const char*, const nlohmann::json*>>& reports,
                                          const Params& params) {
  std::vector<std::string> out;
  for (const auto& [name, report] : reports)
    for (const std::string& d : expectation_differences(stored, expectation_of(*report, params)))
      out.push_back(std::string(name) + ": " + d);
  return out;
}

// Blessing a run whose back ends disagree would store one of them as right.
void bless_expectations(PipelineBench& b, const std::optional<StoredExpectations>& old, const nlohmann::json& blessed,
                        const Params& params) {
  if (b.failures) {
    std::printf("not blessed: %d failure(s) between back ends\n", b.failures);
    return;
  }
  const std::string key = config_key(params);
  const std::vector<std::string> changes = bless_changes(old, blessed, key);
  for (const std::string& c : changes) std::printf("blessing %s\n", c.c_str());
  save_expectations(blessed, key);
  std::printf("blessed %zu input(s) into %s (%zu change(s))\n", blessed.size(), kExpectationFile, changes.size());
}

}  // namespace

PipelineBench run_pipeline_bench(const Params& params, const ConfigFiles& config, const std::string& out_dir, bool bless,
                                 const std::vector<std::string>& inputs) {
  PipelineBench b;
  // Under the thesis' configuration (no --config) on the whole workload
  // list, a missing, stale or incomplete file is a failure: a check that
  // compares nothing must not pass.
  const bool must_compare = config.empty() && inputs.empty() && !bless;
  const std::optional<StoredExpectations> old = load_expectations();
  const bool comparable = old && old->config_key == config_key(params);
  const nlohmann::json stored = comparable ? old->inputs : nlohmann::json();
  if (must_compare && !comparable) {
    std::printf("%s: %s: re-bless with tools/girtd bless\n", kExpectationFile,
                old ? "blessed under another configuration (config/girtd.json changed?)" : "missing");
    ++b.failures;
  }
  nlohmann::json blessed = nlohmann::json::object();
  b.markdown =
      "\n## The SystemC pipeline: approx against rtl (and golden's frame)\n\n"
      "Each render in its own process. Same frame: golden, approx and rtl give the same image SHA-256. Counts: "
      "triangles, pixels by HAD outcome, DDA clocks and clocks per state, HAD busy time, cache accesses and page "
      "misses, approx against rtl. Time: approx's modeled "
      "time against rtl's in base ticks (must be equal). Coupling: wall ns per simulated 5 ns base tick of "
      "rtl in the pipeline against the Verilated back end driven by a plain C++ loop on the same triangles (triangle "
      "traces only). As blessed: every back end's picture, counts and ticks equal the stored expectations (`"
      + std::string(kExpectationFile) + "`; `—` under another configuration).\n\n"
      "| input | pixels | same frame | same counts | as blessed | rtl modeled ms | approx modeled ms | difference (ticks) | rtl wall s | "
      "approx wall s | speed-up | rtl DDA clocks per wall s | rtl wall ns/tick | bare wall ns/tick | coupling cost |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& input : inputs.empty() ? sample_workloads() : inputs) {
    const std::string stem = fs::path(input).parent_path().filename().string() + "_" + fs::path(input).filename().string();
    const nlohmann::json g = render_in_child(input, "golden", out_dir + "/pipeline/" + stem + "/golden", config);
    const nlohmann::json a = render_in_child(input, "approx", out_dir + "/pipeline/" + stem + "/approx", config);
    const nlohmann::json r = render_in_child(input, "rtl", out_dir + "/pipeline/" + stem + "/rtl", config);
    if (g.is_null() || a.is_null() || r.is_null()) {
      b.markdown += "| " + input + " | render failed (the renders' logs: " + out_dir + "/pipeline/" + stem + "/*.log) |\n";
      ++b.failures;
      continue;
    }
    const uint64_t pixels = r.at("pixels_generated");
    const bool same_frame = g.at("image_sha256") == a.at("image_sha256") && a.at("image_sha256") == r.at("image_sha256");
    const bool counts = same_counts(a, r) && g.at("pixels_generated") == r.at("pixels_generated");
    const double rt = r.at("modeled_time_s"), at = a.at("modeled_time_s");
    const double diff = rt > 0 ? (at - rt) / rt : 0.0;
    // The timing model is the RTL's timing: equal to the base tick.
    const double tick_s = params.base_tick_ns * 1e-9;
    const long long diff_ticks = std::llround(at / tick_s) - std::llround(rt / tick_s);
    const bool time_ok = diff_ticks == 0;
    const double rw = r.at("wall_s"), aw = a.at("wall_s");
    const double clocks_per_s = rw > 0 ? r.at("dda_cycles").get<double>() / rw : 0.0;
    // Wall time per simulated base tick, in the pipeline and in the bare
    // harness (which feeds the DDA without the front end's pauses, so it
    // simulates fewer ticks).
    const double ticks = rt / (params.base_tick_ns * 1e-9);
    const double rtl_ns_per_tick = ticks > 0 ? rw / ticks * 1e9 : 0.0;
    double bare = 0;
    if (has_trace_header(input) && header_level(input) == TraceLevel::kTriangle) {
      const TimingComparison c = compare_timing(params, input);
      if (c.rtl.ticks > 0) bare = c.rtl_wall_s / double(c.rtl.ticks) * 1e9;
    }
    std::string as_blessed = "—";
    if (bless) blessed[input] = expectation_of(r, params);
    if (stored.is_object() && !stored.contains(input)) {
      as_blessed = "new";
      if (must_compare) {
        std::printf("%s: not in %s: re-bless with tools/girtd bless\n", input.c_str(), kExpectationFile);
        ++b.failures;
      }
    }
    if (stored.is_object() && stored.contains(input)) {
      const std::vector<std::string> diffs = differences_from(stored.at(input), {{"golden", &g}, {"approx", &a}, {"rtl", &r}}, params);
      as_blessed = diffs.empty() ? "yes" : "NO";
      if (!bless) {  // a bless prints what it changes itself (bless_expectations)
        for (const std::string& d : diffs) std::printf("%s: %s\n", input.c_str(), d.c_str());
        b.failures += !diffs.empty();
      }
    }
    if (!same_frame || !counts || !time_ok) ++b.failures;
    b.rows.push_back({{"input", input}, {"pixels", pixels}, {"same_frame", same_frame}, {"same_counts", counts},
                      {"rtl_modeled_s", rt}, {"approx_modeled_s", at}, {"time_difference", diff},
                      {"time_difference_ticks", diff_ticks}, {"as_blessed", as_blessed}, {"rtl_wall_s", rw}, {"approx_wall_s", aw},
                      {"rtl_dda_clocks_per_wall_s", clocks_per_s}, {"rtl_wall_ns_per_tick", rtl_ns_per_tick},
                      {"bare_rtl_wall_ns_per_tick", bare > 0 ? nlohmann::json(bare) : nlohmann::json(nullptr)}});
    char bare_cells[64] = "— | —";
    if (bare > 0) std::snprintf(bare_cells, sizeof bare_cells, "%.1f | %+.1f %%", bare, 100 * (rtl_ns_per_tick - bare) / bare);
    char line[768];
    std::snprintf(line, sizeof line, "| %s | %llu | %s | %s | %s | %.4f | %.4f | %+lld%s | %.3f | %.3f | %.1fx | %.2e | %.1f | %s |\n",
                  input.c_str(), static_cast<unsigned long long>(pixels), same_frame ? "yes" : "NO", counts ? "yes" : "NO",
                  as_blessed.c_str(), rt * 1e3, at * 1e3, diff_ticks, time_ok ? "" : " (NOT EQUAL)", rw, aw, aw > 0 ? rw / aw : 0.0,
                  clocks_per_s, rtl_ns_per_tick, bare_cells);
    b.markdown += line;
    std::fputs(line, stdout);
    std::fflush(stdout);
  }
  if (bless) bless_expectations(b, old, blessed, params);
  return b;
}

PipelineBench run_option_matrix_bench(const ConfigFiles& config, const std::string& out_dir,
                                      const std::vector<std::string>& inputs) {
  // A stolen cycle every 15.6 us is DRAM refresh's classic period.
  const std::vector<std::pair<std::string, nlohmann::json>> sets = {
      {"write_behind", {{"had", {{"write_behind", true}}}}},
      {"prefetch", {{"had", {{"prefetch", true}}}}},
      {"dirty_bits", {{"had", {{"dirty_bits", true}}}}},
      {"steal_15600ns", {{"vram", {{"steal_every_ns", 15600.0}}}}},
      {"all", {{"had", {{"write_behind", true}, {"prefetch", true}, {"dirty_bits", true}}},
               {"vram", {{"steal_every_ns", 15600.0}}}}}};
  const std::vector<std::string> chosen = inputs.empty() ? read_input_list("traces/accuracy_inputs.txt") : inputs;
  PipelineBench all;
  all.markdown = "\n## Memory-side options: approx against rtl\n";
  for (const auto& [name, overrides] : sets) {
    const std::string dir = out_dir + "/options/" + name;
    fs::create_directories(dir);
    const std::string file = dir + "/options.json";
    std::ofstream(file) << overrides.dump(2) << "\n";
    ConfigFiles with = config;
    with.push_back(file);
    std::printf("options %s: %s\n", name.c_str(), overrides.dump().c_str());
    PipelineBench b = run_pipeline_bench(load_params(with), with, dir, false, chosen);
    for (nlohmann::json& row : b.rows) {
      row["options"] = name;
      all.rows.push_back(row);
    }
    all.markdown += "\n### " + name + ": `" + overrides.dump() + "`\n" + b.markdown;
    all.failures += b.failures;
  }
  return all;
}

WaveCostBench run_wave_cost_bench(const Params& params, const ConfigFiles& config, const std::string& out_dir) {
  WaveCostBench b;
  // The demo trace's DDA parameter sets: all there at once, so the back end
  // never idles (idle ticks are skipped, which would flatter the pipeline).
  const std::string dir = out_dir + "/wave_cost";
  const std::string input = dir + "/demo.dda";
  fs::create_directories(dir);  // --dump writes into an existing folder
  if (render_in_child("traces/demo.trace", "golden", dir + "/dump", config, {"--dump", "dda=" + input}).is_null())
    throw std::runtime_error("cannot dump traces/demo.trace's DDA parameter sets");
  b.markdown =
      "\n## What the coupling and waveforms cost (`traces/demo.trace`'s DDA parameter sets on rtl, best of 3 runs "
      "each)\n\n"
      "Wall time per simulated 5 ns base tick, so runs that simulate different spans compare. Bare: the Verilated "
      "back end driven by a plain C++ loop, no SystemC. rtl_sync = tick: the coupling the pipeline does not use "
      "(SystemC time brought level with the RTL at every tick instead of when a token changes hands). Without "
      "`--wave` the run uses the Verilated build without tracing; with it, the build with FST tracing compiled in, "
      "dumping only inside the window.\n\n"
      "| run | wall s | wall ns per tick | against the pipeline without --wave |\n|---|---|---|---|\n";
  struct Variant {
    std::string what;
    std::vector<std::string> args;
    bool bare = false;
  };
  // A config file asking for the RTL to keep step with SystemC every tick.
  const std::string tick_config = dir + "/sync_every_tick.json";
  std::ofstream(tick_config) << R"({"pipeline": {"rtl_sync": "tick"}})" << "\n";
  std::vector<Variant> variants = {
      {"rtl in the pipeline, no --wave", {}},
      {"bare Verilated harness, same triangles", {}, true},
      {"--wave, a 5 ns window (the traced build and the tick hook, two dumps)",
       {"--wave", dir + "/first.fst", "--wave-window", "0:5"}},
      {"--wave, a 100 us window", {"--wave", dir + "/short.fst", "--wave-window", "30ms:30.1ms"}},
  };
  if (config.empty())  // (with the user's own --config, render would get two)
    variants.insert(variants.begin() + 2, {"no --wave, pipeline.rtl_sync = tick", {"--config", tick_config}});
  double base = 0;
  for (const Variant& v : variants) {
    double best = 0, best_per_tick = 0;
    for (int run = 0; run < 3; ++run) {
      double wall = 0, ticks = 0;
      if (v.bare) {
        const TimingComparison c = compare_timing(params, input);
        wall = c.rtl_wall_s;
        ticks = double(c.rtl.ticks);
      } else {
        const nlohmann::json r = render_in_child(input, "rtl", dir + "/out", config, v.args);
        if (r.is_null()) throw std::runtime_error("wave cost run failed: " + v.what);
        wall = r.at("wall_s");
        ticks = r.at("modeled_time_s").get<double>() / (params.base_tick_ns * 1e-9);
      }
      const double per_tick = wall / ticks * 1e9;
      if (run == 0 || per_tick < best_per_tick) {
        best = wall;
        best_per_tick = per_tick;
      }
    }
    if (base == 0) base = best_per_tick;
    b.rows.push_back({{"run", v.what}, {"wall_s", best}, {"wall_ns_per_tick", best_per_tick},
                      {"ratio", best_per_tick / base}});
    char line[256];
    std::snprintf(line, sizeof line, "| %s | %.3f | %.1f | %.3f |\n", v.what.c_str(), best, best_per_tick,
                  best_per_tick / base);
    b.markdown += line;
    std::fputs(line, stdout);
    std::fflush(stdout);
  }
  return b;
}

}  // namespace girtd
