// girtd render: trace in, frame.png + report.json + report.md out.
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "backends/render_session.hpp"
#include "engine/backend_registry.hpp"
#include "pipeline/pipeline.hpp"
#include "cli/commands.hpp"
#include "cli/config_loader.hpp"
#include "rtl/rtl_build_info.hpp"
#include "io/output_set.hpp"
#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"
#include "io/png_io.hpp"
#include "report/limit_warnings.hpp"
#include "report/report.hpp"
#include "report/report_page.hpp"
#include "io/sha256.hpp"
#include "io/trace_reader.hpp"
#include "backends/front_end_runner.hpp"
#include "io/model_import.hpp"
#include "io/scene_reader.hpp"
#include "io/input_reader.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

DumpRequest parse_dump(const std::string& spec) {
  const size_t eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
    throw InputError("--dump", 0, "expected LEVEL=FILE, got '" + spec + "'");
  const TraceLevel level = parse_level(spec.substr(0, eq), "--dump", 0);
  // A thesis-level trace holds the appendix program's input, which no stage boundary carries.
  if (level == TraceLevel::kThesis)
    throw InputError("--dump", 0, "thesis: not a stage boundary (dump polygon, triangle or dda)");
  return {level, spec.substr(eq + 1)};
}

// The options this back end refuses (its registry entry), before anything is read.
void reject_unbuilt_options(const RenderArgs& a, const BackendEntry& backend) {
  const std::map<std::string, bool> given = {{"--wave", !a.wave.empty()}, {"--sample-timing", bool(a.sample_timing)}};
  for (const BackendRefusal& r : backend.refuses) {
    const auto it = given.find(r.option);
    if (it == given.end()) throw std::logic_error("a refusal of an option render does not have: " + r.option);
    if (it->second) throw InputError(r.option, 0, r.reason);
  }
  // The dump level is checked before the input is read (parse_dump refuses a bad one).
  if (!a.dump.empty() && parse_dump(a.dump).level == TraceLevel::kDda && !backend.has_dda())
    throw InputError("--dump", 0, "dda: the " + backend.name + " back end has no DDA: dump dda from a back end that has one");
  if (a.sample_timing && !(*a.sample_timing > 0 && *a.sample_timing <= 1))
    throw InputError("--sample-timing", 0, "the rate must lie in (0, 1]");
}

// What render draws: the triangle- or DDA-level trace, and for models,
// scenes and polygon traces the polygon-level trace it came from.
struct LoadedInput {
  Trace trace;
  std::optional<Trace> polygons;
  std::optional<FrontendCounts> frontend;
  PrunePlan prune;  // decided on the input as read
};

// `untimed`: golden and reference draw triangles, so the front end runs here;
// the timed back ends run it as their own stages.
LoadedInput load_input(const RenderArgs& a, const Params& params, bool untimed) {
  std::optional<TraceLevel> level;
  if (!a.level.empty()) level = parse_level(a.level, "--level", 0);
  LoadedInput in;
  Trace t = read_input(a.input, level, params);
  if (a.repeat > 1) {  // a static input as N frames: the pipeline overlaps them
    if (t.frames.size() != 1)
      throw InputError("--repeat", 0, a.input + " has " + std::to_string(t.frames.size()) +
                                          " frames: --repeat draws a one-frame input N times");
    t.frames.resize(size_t(a.repeat), t.frames.front());
  }
  if (t.level == TraceLevel::kPolygon) in.polygons = std::move(t);
  else in.trace = std::move(t);
  in.prune = plan_pruning(in.polygons ? *in.polygons : in.trace, !a.no_prune);
  if (in.polygons && untimed) {
    FrontEndRun run = run_front_end(*in.polygons, params, in.prune);
    in.trace = std::move(run.triangles);
    in.frontend = run.counts;
  }
  return in;
}

// The timed back ends' summary: the 20 Mpixel/s verdict and where the time went.
void print_throughput(const nlohmann::json& r) {
  const double t = r["modeled_time_s"];
  const auto& split = r["time_split"];
  auto pct = [&](const char* k) { return 100.0 * split[k].get<double>() / t; };
  const bool sustained = !r["sustained_mpixels_per_s"].is_null();
  std::printf("  throughput %s: %s %.2f Mpixel/s against the %.0f Mpixel/s target (%.6f s modeled; %.2f Mpixel/s over "
              "all frames, %.2f with the DDA fed)\n",
              r["target_met"].get<bool>() ? "PASS" : "FAIL", sustained ? "sustained" : "modeled",
              r[sustained ? "sustained_mpixels_per_s" : "modeled_mpixels_per_s"].get<double>(),
              r["target_mpixels_per_s"].get<double>(), t, r["modeled_mpixels_per_s"].get<double>(),
              r["back_end_mpixels_per_s"].get<double>());
  const std::string bottleneck = r["bottleneck"];
  std::printf("  time       bottleneck %s (busy %.1f %%); DDA busy %.1f %%, on a full FIFO %.1f %%, starved by the "
              "front end %.1f %%; HAD on page swaps %.1f %%; frame clear and swap %.1f %%\n",
              bottleneck.c_str(), 100.0 * r["stages"][bottleneck]["utilization"].get<double>(), pct("dda_busy_s"),
              pct("dda_fifo_full_s"), pct("dda_starved_s"), pct("had_page_wait_s"), pct("frame_clear_swap_s"));
  std::printf("  cache      %llu accesses, %llu page misses, nac %.2f\n",
              static_cast<unsigned long long>(r["cache"]["accesses"].get<uint64_t>()),
              static_cast<unsigned long long>(r["cache"]["page_misses"].get<uint64_t>()),
              r["cache"]["nac"].get<double>());
  if (!r["preparer_triangles_per_s"].is_null())
    std::printf("  preparer   %.0f triangles/s delivered (capacity %.0f; the thesis asks for %.0f)\n",
                r["preparer_triangles_per_s"].get<double>(), r["preparer_capacity_triangles_per_s"].get<double>(),
                r["target_preparer_triangles_per_s"].get<double>());
}

}  // namespace

int run_render(const RenderArgs& a) {
  const BackendEntry& entry = backend_named(a.backend);
  reject_unbuilt_options(a, entry);
  Params params = load_params(a.config);
  if (a.aa) {  // the shorthand for dda.q_override
    params.q_override = *a.aa;
    params.source["dda"]["q_override"] = *a.aa;
  }
  std::optional<WaveOptions> wave;  // checked before the input is read
  if (!a.wave.empty() || !a.wave_window.empty() || !a.wave_scopes.empty())
    wave = parse_wave_options(a.wave, a.wave_window, a.wave_scopes, params.dda_clock_ns, params.base_tick_ns);
  const bool pipelined = entry.timed();
  if (params.q_override && !is_hardware_q(*params.q_override) && entry.has_dda())
    throw InputError(a.aa ? "--aa" : "dda.q_override", 0,
                     "Q must be 0 or a power of two 1/16..8 for the hardware back ends");
  const std::string dir = a.out_dir.empty() ? "out/" + fs::path(a.input).stem().string() : a.out_dir;
  check_output_dir(dir, "--out");
  if (wave) check_output_dir(fs::path(wave->path).parent_path().string(), "--wave");
  const LoadedInput input = load_input(a, params, !pipelined);
  const Trace& trace = input.trace;
  const std::vector<std::string>& warnings = input.polygons ? input.polygons->warnings : trace.warnings;
  for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

  RenderOptions opt;
  opt.keep_all_frames = a.frames == "all";
  if (!a.dump.empty()) opt.dump = parse_dump(a.dump);
  opt.progress = isatty(STDERR_FILENO);
  if (input.polygons) opt.polygon_source = &*input.polygons;
  opt.wave = wave;
  opt.prune = input.prune;
  opt.sample_timing = a.sample_timing;
  RenderOutput out;
  if (pipelined) {
    out = run_pipeline(entry, input.polygons ? *input.polygons : trace, params, opt);
  } else {
    out = render_trace(entry, trace, params, opt);
    out.stats.frontend = input.frontend;
  }
  if (out.problem) {  // not thrown: see WaveFiles
    std::fprintf(stderr, "%s\n", out.problem->formatted().c_str());
    return 2;
  }

  ReportContext ctx;
  ctx.backend = entry.name;
  ctx.capabilities = entry.capabilities;
  ctx.input = a.input;
  ctx.level = level_name(input.polygons ? TraceLevel::kPolygon : trace.level);
  ctx.image_sha256 = sha256_hex(out.shown.rgb);
  ctx.warnings = warnings;
  for (const auto& w : {limit_warning(a.input, out.stats, params), seam_warning(a.input, out.stats),
                        culling_warning(a.input, out.stats)})
    if (w) {  // a hardware limit hit or a seam: counted and warned
      std::fprintf(stderr, "warning: %s\n", w->c_str());
      ctx.warnings.push_back(*w);
    }
  if (out.stats.sampling) {  // never a silently incomplete frame
    const SamplingStats& m = *out.stats.sampling;
    char w[320];
    std::snprintf(w, sizeof w,
                  "%s: sampled timing at rate %g: %llu of %llu triangles drawn, the frame is incomplete; the modeled "
                  "time is an estimate (+-%.3g s at 99.7 %%)",
                  a.input.c_str(), m.rate, static_cast<unsigned long long>(m.measured + m.warmed),
                  static_cast<unsigned long long>(m.measured + m.warmed + m.skipped),
                  m.ci_half_ticks * params.base_tick_ns * 1e-9);
    std::fprintf(stderr, "warning: %s\n", w);
    ctx.warnings.push_back(w);
  }
  if (entry.has(kRunsRtl)) ctx.rtl_build = built_rtl_key();
  ctx.front_end_passes = front_end_passes();
  ctx.left_out = left_out(out.stats);
  const std::optional<ChartLibrary> charts = load_chart_library();
  // The machine's, not the input's: on stderr, not in report.json.
  if (!charts) std::fprintf(stderr, "warning: report.html: %s\n", kNoChartLibrary);
  const nlohmann::json report = make_report(ctx, out.stats, params);

  OutputSet files(dir);
  const std::string frame_png = png_rgb_bytes(out.shown);  // frame.png and the page's picture: encoded once
  files.add_text("frame.png", frame_png);
  for (size_t i = 0; i < out.per_frame.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%03zu.png", i);
    files.add(name, [&, i](const std::string& p) { write_png_rgb(p, out.per_frame[i]); });
  }
  if (a.z_png)
    files.add("z.png", [&](const std::string& p) { write_png_gray16(p, out.shown.width, out.shown.height, out.z); });
  files.add_text("report.json", report.dump(2) + "\n");
  files.add_text("report.md", report_markdown(report));
  std::optional<FrameComparison> compare;
  if (!a.compare.empty()) {  // the same input on the picture yardstick, in this process (it is untimed)
    const BackendEntry& yardstick = backend_named(a.compare);
    const LoadedInput ref_input = load_input(a, params, true);
    RenderOptions ref_opt;
    ref_opt.prune = ref_input.prune;
    compare = FrameComparison{yardstick.name, render_trace(yardstick, ref_input.trace, params, ref_opt).shown};
  }
  files.add("report.html", [&](const std::string& p) {
    std::ofstream(p) << report_html(report_page_data(report, out.stats), out.shown, frame_png, out.stats, compare, charts);
  });
  files.commit();

  if (!a.quiet) {
    const RunStats& s = out.stats;
    std::printf("girtd render: %s on the %s back end, %llu frame(s)\n", a.input.c_str(), ctx.backend.c_str(),
                static_cast<unsigned long long>(s.frames));
    if (s.frontend)
      std::printf("  front end  %llu polygons: %llu culled, %llu clipped, %llu clipped away; %llu triangles made, "
                  "%llu off the window, %llu out\n",
                  static_cast<unsigned long long>(s.frontend->polygons), static_cast<unsigned long long>(s.frontend->culled),
                  static_cast<unsigned long long>(s.frontend->clipped),
                  static_cast<unsigned long long>(s.frontend->clipped_away),
                  static_cast<unsigned long long>(s.frontend->triangles_made),
                  static_cast<unsigned long long>(s.frontend->discarded_off_window),
                  static_cast<unsigned long long>(s.frontend->triangles_out));
    std::printf("  triangles  %llu in, %llu drawn\n", static_cast<unsigned long long>(s.triangles_in),
                static_cast<unsigned long long>(s.triangles_drawn));
    std::printf("  pixels     %llu generated: %llu written, %llu blended, %llu z-rejected, %llu dropped\n",
                static_cast<unsigned long long>(s.pixels_generated), static_cast<unsigned long long>(s.had.written),
                static_cast<unsigned long long>(s.had.blended), static_cast<unsigned long long>(s.had.z_rejected),
                static_cast<unsigned long long>(s.had.dropped));
    if (s.dda)
      std::printf("  DDA        %llu clocks, efficiency %.1f %%, %.2f Mpixel/s DDA-bound at %.0f ns\n",
                  static_cast<unsigned long long>(s.dda->cycles), 100.0 * report["dda_efficiency"].get<double>(),
                  report["dda_bound_mpixels_per_s"].get<double>(), params.dda_clock_ns);
    if (s.timing) print_throughput(report);
    std::printf("  wall       %.3f s\n", s.wall_s);
    std::printf("  image      %s\n  report     %s\n", files.path("frame.png").c_str(),
                files.path("report.json").c_str());
    if (opt.dump) std::printf("  dump       %s\n", opt.dump->path.c_str());
    if (!out.wave_files.empty())
      std::printf("  waveform   %s (open: gtkwave %s %s)\n", out.wave_files[0].c_str(), out.wave_files[0].c_str(),
                  out.wave_files[1].c_str());
    if (out.wave_files.size() > 2) std::printf("  pixel log  %s (pixels the DDA pushed in the window)\n", out.wave_files[2].c_str());
  }
  return 0;
}

}  // namespace girtd
