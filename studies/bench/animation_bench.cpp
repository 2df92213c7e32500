#include "bench/animation_bench.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "bench/user_render.hpp"
#include "io/json_file.hpp"
#include "io/subprocess.hpp"
#include "io/text_format.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

constexpr double kFlatMemory = 1.1;  // the long run's peak over the short one's

std::string mesh_name() { return "turning_sphere_" + std::to_string(kAnimationTriangles) + ".obj"; }

// The sphere turning 0.36 degrees a frame about Y, seen from a fixed camera.
std::string write_scene(const std::string& dir, long frames) {
  nlohmann::json list = nlohmann::json::array();
  for (long f = 0; f < frames; ++f) list.push_back({{"models", {{"sphere", {{"rotate_deg", {0, 0.36 * double(f), 0}}}}}}});
  const nlohmann::json scene = {{"girtd_scene", 1},
                                {"comment", "girtd bench --scale: a sphere turning over " + std::to_string(frames) + " frames"},
                                {"camera", {{"eye", {0, 0, 4}}, {"target", {0, 0, 0}}}},
                                {"models", {{{"name", "sphere"}, {"file", mesh_name()}}}},
                                {"frames", list}};
  const std::string path = dir + "/turning_" + std::to_string(frames) + ".json";
  std::ofstream(path) << scene.dump() << "\n";
  return path;
}

}  // namespace

std::vector<std::string> animation_bench_plan_lines(const std::string& out_dir) {
  return {"mesh\t" + std::to_string(kAnimationTriangles) + "\t" + out_dir + "/scale/" + mesh_name()};
}

AnimationBench run_animation_bench(const std::string& out_dir, long short_frames, long long_frames) {
  AnimationBench b;
  const std::string dir = out_dir + "/scale";
  auto fail = [&b](const std::string& what) {
    std::fprintf(stderr, "\nbench: %s\n", what.c_str());
    ++b.failures;
  };
  if (!fs::exists(dir + "/" + mesh_name())) {
    fail("the mesh " + dir + "/" + mesh_name() + " is not there: tools/girtd bench --scale makes it first");
    return b;
  }
  const std::string render = user_render_program(), log = dir + "/runs.log";
  b.rows = nlohmann::json::array();
  b.markdown = "\n## Long animations: memory against the frame count\n\nA UV sphere of about " +
               format_numbers("%.0f", double(kAnimationTriangles)) +
               " triangles turning, one scene per frame count, each rendered once with `" + user_render_name() +
               " SCENE --backend B` (`--frames last`); peak: the process's largest resident memory. The bar: the long "
               "run's peak at most " + format_numbers("%.1f", kFlatMemory) +
               "x the short one's (a memory bar: peak memory repeats from run to run, so no margin for noise).\n\n"
               "| back end | frames | peak MB | elapsed s | frames | peak MB | elapsed s | long / short peak | verdict |\n"
               "|---|---|---|---|---|---|---|---|---|\n";
  for (const char* backend : {"golden", "approx", "rtl"}) {
    const long frames[2] = {short_frames,
                            std::string(backend) == "rtl" ? std::min(long_frames, kLongAnimationRtl) : long_frames};
    ProcessUsage use[2];
    for (int k = 0; k < 2; ++k) {
      if (isatty(STDERR_FILENO))
        std::fprintf(stderr, "\r[girtd] bench --scale: %s, %ld frames   ", backend, frames[k]);
      const std::string scene = write_scene(dir, frames[k]);
      const std::string out = dir + "/" + backend + "_turning_" + std::to_string(frames[k]);
      use[k] = run_process_measured({render, "render", scene, "--backend", backend, "--out", out, "--quiet"}, log);
      if (use[k].exit_code != 0) {
        fail("a run on " + scene + " (" + backend + ") failed (" + log + ")");
        return b;
      }
      const long drawn = read_json_file(out + "/report.json").at("frames").get<long>();
      if (drawn != frames[k]) {
        fail(scene + ": " + backend + " drew " + std::to_string(drawn) + " frames, not " + std::to_string(frames[k]));
        return b;
      }
    }
    const double ratio = use[1].peak_rss_mb / use[0].peak_rss_mb;
    b.rows.push_back({{"backend", backend},
                      {"short", {{"frames", frames[0]}, {"peak_mb", use[0].peak_rss_mb}, {"elapsed_s", use[0].elapsed_s}}},
                      {"long", {{"frames", frames[1]}, {"peak_mb", use[1].peak_rss_mb}, {"elapsed_s", use[1].elapsed_s}}},
                      {"long_over_short_peak", ratio}});
    b.markdown += std::string("| ") + backend + " | " + std::to_string(frames[0]) + " | " +
                  format_numbers("%.1f", use[0].peak_rss_mb) + " | " + format_numbers("%.1f", use[0].elapsed_s) + " | " +
                  std::to_string(frames[1]) + " | " + format_numbers("%.1f", use[1].peak_rss_mb) + " | " +
                  format_numbers("%.1f", use[1].elapsed_s) + " | " + format_numbers("%.3f", ratio) + " | " +
                  (ratio <= kFlatMemory ? "met" : "not met") + " |\n";
  }
  if (isatty(STDERR_FILENO)) std::fprintf(stderr, "\n");
  return b;
}

}  // namespace girtd
