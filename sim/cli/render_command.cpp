// girtd render: trace in, frame.png + report.json + report.md out.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "api/girtd.hpp"
#include "cli/commands.hpp"
#include "io/output_set.hpp"
#include "report/page_parts.hpp"
#include "report/report.hpp"
#include "report/report_page.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

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
  const std::string dir = a.out_dir.empty() ? "out/" + fs::path(a.input).stem().string() : a.out_dir;
  check_output_dir(dir, "--out");
  RenderRequest request;
  request.input = a.input;
  request.backend = a.backend;
  for (const std::string& f : a.config) request.config.push_back({f, nullptr, f});
  request.level = a.level;
  request.camera = a.camera;
  request.repeat = a.repeat;
  request.prune = !a.no_prune;
  request.aa = a.aa;
  request.sample_timing = a.sample_timing;
  request.dump = a.dump;
  request.wave = a.wave;
  request.wave_window = a.wave_window;
  request.wave_scopes = a.wave_scopes;
  request.progress = isatty(STDERR_FILENO);
  OutputSet files(dir);
  if (a.frames == "all")  // each frame's PNG as the frame ends: a long animation holds none
    request.on_frame = [&files](size_t i, const RgbImage& picture) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%03zu.png", i);
      files.write_now(name, [&](const std::string& p) { write_png_rgb(p, picture); });
    };
  const RenderResult out = render(request);
  if (out.problem) {
    std::fprintf(stderr, "%s\n", out.problem->formatted().c_str());
    return 2;
  }
  const nlohmann::json& report = out.report;
  const std::optional<ChartLibrary> charts = load_chart_library();
  // The machine's, not the input's: on stderr, not in report.json.
  if (!charts) std::fprintf(stderr, "warning: report.html: %s\n", kNoChartLibrary);

  const std::string frame_png = png_rgb_bytes(out.frame);  // frame.png and the page's picture: encoded once
  files.add_text("frame.png", frame_png);
  if (a.z_png)
    files.add("z.png", [&](const std::string& p) { write_png_gray16(p, out.frame.width, out.frame.height, out.z); });
  // A path holding a byte of no UTF-8 character is replaced, not fatal.
  files.add_text("report.json", report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  files.add_text("report.md", report_markdown(report));
  std::optional<FrameComparison> compare;
  if (!a.compare.empty()) {  // the same input on the picture yardstick, in this process (it is untimed)
    RenderRequest yardstick = request;
    yardstick.backend = a.compare;
    yardstick.on_frame = nullptr;
    yardstick.dump.clear();
    yardstick.sample_timing.reset();
    yardstick.wave.clear();
    yardstick.wave_window.clear();
    yardstick.wave_scopes.clear();
    yardstick.progress = false;
    yardstick.print_warnings = false;  // the same input's, said once
    compare = FrameComparison{a.compare, render(yardstick).frame};
  }
  files.add("report.html", [&](const std::string& p) {
    std::ofstream(p) << report_html(report_page_data(report, out.stats), out.frame, frame_png, out.stats, compare, charts);
  });
  files.commit();

  if (!a.quiet) {
    const RunStats& s = out.stats;
    std::printf("girtd render: %s on the %s back end, %llu frame(s)\n", a.input.c_str(), a.backend.c_str(),
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
                  report["dda_bound_mpixels_per_s"].get<double>(), report["config"]["dda"]["clock_ns"].get<double>());
    if (s.timing) print_throughput(report);
    std::printf("  wall       %.3f s\n", s.wall_s);
    std::printf("  image      %s\n  report     %s\n", files.path("frame.png").c_str(),
                files.path("report.json").c_str());
    if (!a.dump.empty()) std::printf("  dump       %s\n", a.dump.substr(a.dump.find('=') + 1).c_str());
    if (!out.wave_files.empty())
      std::printf("  waveform   %s (open: gtkwave %s %s)\n", out.wave_files[0].c_str(), out.wave_files[0].c_str(),
                  out.wave_files[1].c_str());
    if (out.wave_files.size() > 2) std::printf("  pixel log  %s (pixels the DDA pushed in the window)\n", out.wave_files[2].c_str());
  }
  return 0;
}

}  // namespace girtd
