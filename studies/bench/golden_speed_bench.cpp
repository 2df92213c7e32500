#include "bench/golden_speed_bench.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "accuracy/llvmpipe_render.hpp"
#include "bench/bench_stats.hpp"
#include "cli/child_render.hpp"
#include "io/trace_reader.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

constexpr int kRuns = 7;
constexpr int kTriangles = 20000;
constexpr double kWithin = 2.0;  // golden at most this many times llvmpipe's time

std::string workload_path(const std::string& out_dir) { return out_dir + "/golden_speed/opaque_20000.trace"; }

}  // namespace

std::string golden_speed_bench_plan_line(const std::string& out_dir) {
  return "opaque-trace\t" + std::to_string(kTriangles) + "\t" + workload_path(out_dir);
}

GoldenSpeedBench run_golden_speed_bench(const Params& params, const ConfigFiles& config, const std::string& out_dir) {
  GoldenSpeedBench b;
  const std::string dir = out_dir + "/golden_speed";
  fs::create_directories(dir);
  b.markdown = "\n## golden against Mesa's llvmpipe (single-threaded), " + std::to_string(kRuns) +
               " pairs\n\n"
               "20,000 random opaque 200-pixel triangles (`tools/make_opaque_trace.py 20000`, Q = 0, Z test). golden: "
               "report.json's `wall_s`, each render in its own process; llvmpipe: clear to `glFinish` through OSMesa "
               "(`LP_NUM_THREADS=0`), after one untimed draw of the same triangles in the same context (its shaders "
               "compiled). Both from the triangles in memory to the final colour and Z buffers. The two run in turn, "
               "pair by pair, each first every other time; the times are the medians of each, the ratio the median "
               "of the pairs' ratios.\n\n"
               "| workload | pixels | golden wall s | llvmpipe s | golden / llvmpipe | within 2x |\n"
               "|---|---|---|---|---|---|\n";
  auto fail = [&b](const std::string& what) {
    std::fprintf(stderr, "bench: %s\n", what.c_str());
    ++b.failures;
    b.markdown += "| " + what + " |\n";
    return b;
  };
  // Made by the driver (tools/girtd's step for golden_speed_bench_plan_line).
  const std::string trace = workload_path(out_dir);
  if (!fs::exists(trace))
    return fail("the workload " + trace + " is not there: tools/girtd bench --speed makes it first "
                "(tools/make_opaque_trace.py " + std::to_string(kTriangles) + ")");
  std::vector<Triangle> triangles;
  Rgb background;
  try {
    const Trace t = read_trace(trace, std::nullopt, params);
    triangles = t.frames.at(0).triangles;
    background = t.frames[0].settings.background;
  } catch (const std::exception& e) {
    return fail(std::string("the workload could not be read: ") + e.what());
  }
  // Pair by pair (run_pairs), golden's render and llvmpipe's draw: a burst
  // of load on this shared host then weighs on both sides of a pair, not on
  // one side of the whole comparison.
  nlohmann::json r;
  std::string problem;
  std::vector<double> golden, llvmpipe, ratios;
  auto golden_run = [&] {
    r = render_in_child(trace, "golden", dir + "/golden", config);
    if (r.is_null() || !r.contains("wall_s")) {
      problem = "golden's render failed";
      return false;
    }
    golden.push_back(r.at("wall_s").get<double>());
    return true;
  };
  auto llvmpipe_run = [&] {
    try {
      llvmpipe.push_back(render_llvmpipe(triangles, params.screen_width, params.screen_height, background,
                                         static_cast<uint16_t>(params.depth_clear))
                             .draw_s);
      return true;
    } catch (const std::exception& e) {
      problem = std::string("llvmpipe failed: ") + e.what();
      return false;
    }
  };
  if (!run_pairs(kRuns, golden_run, llvmpipe_run,
                 [&] { ratios.push_back(llvmpipe.back() > 0 ? golden.back() / llvmpipe.back() : 0); }))
    return fail(problem);
  const double g = median(golden), l = median(llvmpipe), ratio = median(ratios);
  const bool within = ratio > 0 && ratio <= kWithin;
  const double pixels = r.at("pixels_generated").get<double>();
  b.rows.push_back({{"workload", "20000 random opaque 200-px triangles"}, {"triangles", kTriangles},
                    {"pixels_generated", pixels}, {"pairs", kRuns}, {"golden_wall_s", g}, {"llvmpipe_s", l},
                    {"ratio", ratio}, {"within_2x", within}});
  char line[256];
  std::snprintf(line, sizeof line, "| %d random opaque 200-px triangles | %.0f | %.3f | %.3f | %.2fx | %s |\n", kTriangles,
                pixels, g, l, ratio, within ? "yes" : "no");
  b.markdown += line;
  std::fputs(line, stdout);
  std::fflush(stdout);
  return b;
}

}  // namespace girtd
