// girtd bench: every sample trace on the functional back ends (wall time,
// pixel rate of the simulator, the frame's error against the reference), the
// back end's two timing engines side by side, and the SystemC pipeline's
// approx against rtl (pipeline_bench.hpp). --pipeline: that table alone.
#include <unistd.h>

#include <cmath>
#include <ctime>
#include <thread>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "accuracy/accuracy_table.hpp"
#include "backends/render_session.hpp"
#include "engine/backend_registry.hpp"
#include "bench/bench_command.hpp"
#include "cli/config_loader.hpp"
#include "io/output_set.hpp"
#include "bench/leave_out_bench.hpp"
#include "bench/golden_speed_bench.hpp"
#include "bench/rtl_speed_bench.hpp"
#include "bench/series_cost_bench.hpp"
#include "bench/pipeline_bench.hpp"
#include "bench/animation_bench.hpp"
#include "bench/scale_bench.hpp"
#include "io/image_compare.hpp"
#include "io/workload_list.hpp"
#include "common/input_error.hpp"
#include "io/trace_reader.hpp"
#include "rtl/timing_comparison.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

// When and where: the READMEs quote bench.json (studies/bench_summary.py).
nlohmann::json measured_on() {
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  char host[256] = "";
  gethostname(host, sizeof host - 1);
  return {{"date", date}, {"host", host}, {"cores", std::thread::hardware_concurrency()}};
}

}  // namespace

int run_bench(const BenchArgs& a) {
  const ConfigFiles& config = a.config;
  const std::string& out_dir = a.out;
  const bool bless = a.bless;
  const Params params = load_params(config);
  if (bless && !config.empty())
    throw InputError("--bless", 0, "the stored expectations are the thesis configuration's: bless without --config");
  if (a.pipeline_only) {
    const PipelineBench pb = a.option_matrix ? run_option_matrix_bench(config, out_dir, a.inputs)
                                             : run_pipeline_bench(params, config, out_dir, bless, a.inputs);
    OutputSet files(out_dir);
    files.add_text("pipeline.json", nlohmann::json{{"rows", pb.rows}, {"config", params.source}}.dump(2) + "\n");
    files.add_text("pipeline.md", "# girtd bench --pipeline\n" + pb.markdown);
    files.commit();
    std::printf("%d failure(s) (back ends disagreeing, or differing from the stored expectations); wrote %s\n", pb.failures,
                files.path("pipeline.md").c_str());
    return pb.failures ? 1 : 0;
  }
  if (a.speed_only) {
    const RtlSpeedBench rb = run_rtl_speed_bench(params, config, out_dir);
    const GoldenSpeedBench gb = run_golden_speed_bench(params, config, out_dir);
    const SeriesCostBench sb = run_series_cost_bench(config, out_dir);
    OutputSet files(out_dir);
    files.add_text("speed.json", nlohmann::json{{"measured_on", measured_on()}, {"rtl_speed", rb.rows},
                                                {"golden_vs_llvmpipe", gb.rows}, {"series_cost", sb.rows},
                                                {"config", params.source}}
                                     .dump(2) + "\n");
    files.add_text("speed.md", "# girtd bench --speed\n" + rb.markdown + gb.markdown + sb.markdown);
    files.commit();
    const int failures = rb.failures + gb.failures + sb.failures;
    std::printf("%d failure(s); wrote %s\n", failures, files.path("speed.md").c_str());
    return failures ? 1 : 0;
  }
  if (a.scale_only) {
    if (!config.empty()) throw InputError("--config", 0, "bench --scale renders with the default configuration");
    if (a.animation_frames.at(0) >= a.animation_frames.at(1))
      throw InputError("--frames", 0, "the short frame count comes first and is the smaller");
    const ScaleBench sb = run_scale_bench(out_dir, a.scale_sizes, a.scale_runs);
    const AnimationBench ab = sb.failures ? AnimationBench{}
                                          : run_animation_bench(out_dir, a.animation_frames.at(0), a.animation_frames.at(1));
    if (sb.failures || ab.failures) {  // nothing half-measured for docs --record to take
      std::printf("%d failure(s); nothing written\n", sb.failures + ab.failures);
      return 1;
    }
    OutputSet files(out_dir);
    files.add_text("scale.json",
                   nlohmann::json{{"measured_on", measured_on()}, {"scale", sb.rows}, {"animation", ab.rows}}.dump(2) + "\n");
    files.add_text("scale.md", "# girtd bench --scale\n" + sb.markdown + ab.markdown);
    files.commit();
    std::fputs((sb.markdown + ab.markdown).c_str(), stdout);
    std::printf("0 failure(s); wrote %s\n", files.path("scale.md").c_str());
    return 0;
  }
  if (a.leave_out_only) {
    const LeaveOutBench lb = run_leave_out_bench(config, out_dir);
    OutputSet files(out_dir);
    files.add_text("leave_out.json", nlohmann::json{{"measured_on", measured_on()}, {"culling", lb.culling},
                                                    {"pruning", lb.pruning}, {"pruning_ceiling", lb.pruning_ceiling},
                                                    {"config", params.source}}
                                             .dump(2) + "\n");
    files.add_text("leave_out.md", "# girtd bench --leave-out\n" + lb.markdown);
    files.commit();
    std::printf("%d failure(s); wrote %s\n", lb.failures, files.path("leave_out.md").c_str());
    return lb.failures ? 1 : 0;
  }
  nlohmann::json rows = nlohmann::json::array();
  std::string md =
      "| trace | back end | triangles | pixels | wall s | sim Mpixel/s | mean abs err | max abs err | pixels differing |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& path : sample_traces_at({TraceLevel::kTriangle})) {
    const Trace trace = read_trace(path, std::nullopt, params);
    RenderOutput reference;
    std::vector<const BackendEntry*> untimed = {&backend_with(kExactPicture)};  // the picture yardstick first
    for (const BackendEntry& b : backend_registry())
      if (!b.timed() && !b.has(kExactPicture)) untimed.push_back(&b);
    for (const BackendEntry* e : untimed) {
      const BackendEntry& entry = *e;
      const std::string& name = entry.name;
      FrameSource input(trace);
      const RenderOutput out = render_frames(entry, input, params, {});
      if (entry.has(kExactPicture)) reference = out;
      // The accuracy command's picture error (accuracy/accuracy_table.hpp).
      const ImageError err = compare_images(out.shown, reference.shown);
      const DepthError derr = compare_depth(out.z, reference.z, static_cast<uint16_t>(params.depth_clear));
      const double rate = out.stats.wall_s > 0 ? double(out.stats.pixels_generated) / out.stats.wall_s / 1e6 : 0;
      rows.push_back({{"trace", path}, {"backend", name}, {"triangles", out.stats.triangles_in},
                      {"pixels_generated", out.stats.pixels_generated}, {"wall_s", out.stats.wall_s},
                      {"sim_mpixels_per_s", rate}, {"mean_abs_error", err.mean_abs}, {"max_abs_error", err.max_abs},
                      {"differing_fraction", err.differing_fraction}, {"image", picture_error_cell(err, derr)}});
      char line[512];
      std::snprintf(line, sizeof line, "| %s | %s | %llu | %llu | %.3f | %.2f | %.4f | %d | %.4f %% |\n",
                    fs::path(path).filename().c_str(), name.c_str(),
                    static_cast<unsigned long long>(out.stats.triangles_in),
                    static_cast<unsigned long long>(out.stats.pixels_generated), out.stats.wall_s, rate, err.mean_abs,
                    err.max_abs, 100 * err.differing_fraction);
      md += line;
      std::fputs(line, stdout);
      std::fflush(stdout);
    }
  }
  // The back end's two timing engines on the same traces: the Verilated RTL
  // and the approx back end's timing model, bare (no pipeline).
  std::string md2 =
      "\n## Back-end timing: RTL against the timing model\n\n"
      "| trace | pixels | RTL modeled ms | model modeled ms | difference | RTL wall s | model wall s | speed-up | "
      "RTL DDA clocks per wall s |\n|---|---|---|---|---|---|---|---|---|\n";
  nlohmann::json timing_rows = nlohmann::json::array();
  for (const std::string& path : sample_traces_at({TraceLevel::kTriangle})) {
    const TimingComparison c = compare_timing(params, path);
    const double rtl_ms = double(c.rtl.ticks) * params.base_tick_ns * 1e-6;
    const double model_ms = double(c.model.ticks) * params.base_tick_ns * 1e-6;
    const double diff = rtl_ms > 0 ? (model_ms - rtl_ms) / rtl_ms : 0;
    timing_rows.push_back({{"trace", path}, {"pixels", c.model.pixels_generated}, {"rtl_modeled_s", rtl_ms * 1e-3},
                           {"model_modeled_s", model_ms * 1e-3}, {"rtl_wall_s", c.rtl_wall_s},
                           {"model_wall_s", c.model_wall_s},
                           {"rtl_dda_clocks_per_wall_s", double(c.rtl.dda.cycles) / c.rtl_wall_s}});
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %llu | %.3f | %.3f | %+.5f %% | %.3f | %.3f | %.1fx | %.2e |\n",
                  fs::path(path).filename().c_str(), static_cast<unsigned long long>(c.model.pixels_generated), rtl_ms, model_ms,
                  100 * diff, c.rtl_wall_s, c.model_wall_s, c.model_wall_s > 0 ? c.rtl_wall_s / c.model_wall_s : 0,
                  double(c.rtl.dda.cycles) / c.rtl_wall_s);
    md2 += line;
    std::fputs(line, stdout);
    std::fflush(stdout);
  }
  md += md2;
  const PipelineBench pb = run_pipeline_bench(params, config, out_dir);
  md += pb.markdown;
  const WaveCostBench wb = run_wave_cost_bench(params, config, out_dir);
  md += wb.markdown;
  const SeriesCostBench sb = run_series_cost_bench(config, out_dir);
  md += sb.markdown;
  const LeaveOutBench lb = run_leave_out_bench(config, out_dir);
  md += lb.markdown;
  OutputSet files(out_dir);
  files.add_text("bench.json", nlohmann::json{{"measured_on", measured_on()},
                                              {"rows", rows},
                                              {"timing", timing_rows},
                                              {"pipeline", pb.rows},
                                              {"wave_cost", wb.rows},
                                              {"series_cost", sb.rows},
                                              {"culling", lb.culling},
                                              {"pruning", lb.pruning},
                                              {"pruning_ceiling", lb.pruning_ceiling},
                                              {"config", params.source}}
                                       .dump(2) +
                                   "\n");
  files.add_text("bench.md", "# girtd bench\n\nError is against the reference back end's frame (0..255 per channel; "
                            "bench.json's `image` cells as `girtd accuracy` writes them).\n\n" + md);
  files.commit();
  std::printf("wrote %s and %s\n", files.path("bench.json").c_str(), files.path("bench.md").c_str());
  if (pb.failures) std::printf("%d failure(s) in the pipeline table (see above)\n", pb.failures);
  if (lb.failures) std::printf("%d failure(s) in the culling and pruning tables (see above)\n", lb.failures);
  if (sb.failures) std::printf("%d failure(s) in the series cost table (see above)\n", sb.failures);
  return pb.failures || lb.failures || sb.failures ? 1 : 0;
}

}  // namespace girtd
