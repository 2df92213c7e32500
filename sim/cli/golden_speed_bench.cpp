#include "cli/golden_speed_bench.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "accuracy/llvmpipe_render.hpp"
#include "cli/bench_stats.hpp"
#include "cli/child_render.hpp"
#include "io/subprocess.hpp"
#include "io/trace_reader.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

constexpr int kRuns = 7;
constexpr int kTriangles = 20000;
constexpr double kWithin = 2.0;  // golden at most this many times llvmpipe's time

}  // namespace

GoldenSpeedBench run_golden_speed_bench(const Params& params, const ConfigFiles& config, const std::string& out_dir) {
  GoldenSpeedBench b;
  const std::string dir = out_dir + "/golden_speed";
  fs::create_directories(dir);
  b.markdown =
      "\n## golden against Mesa's llvmpipe (single-threaded), 7 pairs\n\n"
      "20,000 random opaque 200-pixel triangles (`tools/make_opaque_trace.py 20000`, Q = 0, Z test). golden: "
      "report.json's `wall_s`, each render in its own process; llvmpipe: clear to `glFinish` through OSMesa "
      "(`LP_NUM_THREADS=0`), after one untimed draw of the same triangles in the same context (its shaders "
      "compiled). Both from the triangles in memory to the final colour and Z buffers. The two run in turn, "
      "pair by pair; the times are the medians of each, the ratio the median of the pairs' ratios.\n\n"
      "| workload | pixels | golden wall s | llvmpipe s | golden / llvmpipe | within 2x |\n"
      "|---|---|---|---|---|---|\n";
  const std::string trace = dir + "/opaque_20000.trace";
  if (run_process({"python3", "tools/make_opaque_trace.py", std::to_string(kTriangles), "--out", trace}, false) != 0) {
    ++b.failures;
    b.markdown += "| the workload could not be made (tools/make_opaque_trace.py) |\n";
    return b;
  }
  // Pair by pair, golden's render then llvmpipe's draw: a burst of load on
  // this shared host then weighs on both sides of a pair, not on one side
  // of the whole comparison. The ratio is the median of the pairs'.
  std::vector<double> golden, llvmpipe, ratios;
  nlohmann::json r;
  try {
    const Trace t = read_trace(trace, std::nullopt, params);
    for (int i = 0; i < kRuns; ++i) {
      r = render_in_child(trace, "golden", dir + "/golden", config);
      if (r.is_null()) break;
      golden.push_back(r.at("wall_s"));
      llvmpipe.push_back(render_llvmpipe(t.frames.at(0).triangles, params.screen_width, params.screen_height,
                                         t.frames[0].settings.background, static_cast<uint16_t>(params.depth_clear))
                             .draw_s);
      ratios.push_back(llvmpipe.back() > 0 ? golden.back() / llvmpipe.back() : 0);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench: llvmpipe: %s\n", e.what());
    llvmpipe.clear();
  }
  if (r.is_null() || llvmpipe.size() < kRuns) {
    ++b.failures;
    b.markdown += r.is_null() ? "| golden's render failed |\n" : "| llvmpipe failed |\n";
    return b;
  }
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
