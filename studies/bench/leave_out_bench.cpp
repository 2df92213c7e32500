#include "bench/leave_out_bench.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "bench/bench_stats.hpp"
#include "cli/child_render.hpp"
#include "io/image_compare.hpp"
#include "io/png_io.hpp"
#include "io/workload_list.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

constexpr int kPruneRuns = 5;
constexpr int kCeilingPairs = 11;
constexpr const char* kOutOfView = "traces/scenes/out_of_view.json";
constexpr const char* kCullingPreset = "config/presets/culling.json";

// Everything in a report but what pruning may change.
nlohmann::json without_wall(nlohmann::json r) {
  r.erase("wall_s");
  r.erase("left_out");
  return r;
}

void culling_table(const ConfigFiles& config, const std::string& dir, LeaveOutBench& b) {
  const std::string objects_only = dir + "/objects_only.json";
  std::ofstream(objects_only) << R"({"culling": {"objects": true}})" << "\n";
  b.markdown +=
      "\n## Culling in front of lighting (approx, modeled)\n\n"
      "`culling.objects` alone, then `config/presets/culling.json` (objects and back faces); the frame with "
      "object culling against the thesis' design's, and how many pixels culling back faces changed.\n\n"
      "| scene | polygons | objects culled (polygons) | back faces culled | thesis ms | Mpixel/s | objects ms | "
      "Mpixel/s | frame | both ms | Mpixel/s | pixels changed |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& input : sample_workloads()) {
    if (fs::path(input).extension() != ".json") continue;
    const std::string base = dir + "/culling/" + fs::path(input).stem().string();
    ConfigFiles with_objects = config, with_both = config;
    with_objects.push_back(objects_only);
    with_both.push_back(kCullingPreset);
    const nlohmann::json t = render_in_child(input, "approx", base + "-thesis", config);
    const nlohmann::json o = render_in_child(input, "approx", base + "-objects", with_objects);
    const nlohmann::json a = render_in_child(input, "approx", base + "-both", with_both);
    if (t.is_null() || o.is_null() || a.is_null()) {
      ++b.failures;
      b.markdown += "| " + input + " | render failed |\n";
      continue;
    }
    const bool same = t.at("image_sha256") == o.at("image_sha256");
    b.failures += !same;  // object culling must leave the frame as it was
    const uint64_t changed =
        compare_images(read_png_rgb(base + "-thesis/frame.png"), read_png_rgb(base + "-both/frame.png")).differing;
    auto ms = [](const nlohmann::json& r) { return r.at("modeled_time_s").get<double>() * 1e3; };
    auto rate = [](const nlohmann::json& r) { return r.at("modeled_mpixels_per_s").get<double>(); };
    const nlohmann::json& of = o.at("frontend");
    b.culling.push_back({{"input", input}, {"polygons", of.at("polygons")}, {"objects", of.at("objects")},
                         {"objects_culled", of.at("objects_culled")},
                         {"object_culled_polygons", of.at("object_culled_polygons")},
                         {"back_faces_culled", a.at("frontend").at("culled")},
                         {"thesis_modeled_s", t.at("modeled_time_s")}, {"objects_modeled_s", o.at("modeled_time_s")},
                         {"both_modeled_s", a.at("modeled_time_s")}, {"thesis_mpixels_per_s", rate(t)},
                         {"objects_mpixels_per_s", rate(o)}, {"both_mpixels_per_s", rate(a)},
                         {"objects_same_frame", same}, {"both_pixels_changed", changed}});
    char line[512];
    std::snprintf(line, sizeof line,
                  "| %s | %llu | %llu of %llu (%llu) | %llu | %.2f | %.2f | %.2f | %.2f | %s | %.2f | %.2f | %llu |\n",
                  fs::path(input).filename().c_str(), of.at("polygons").get<unsigned long long>(),
                  of.at("objects_culled").get<unsigned long long>(), of.at("objects").get<unsigned long long>(),
                  of.at("object_culled_polygons").get<unsigned long long>(),
                  a.at("frontend").at("culled").get<unsigned long long>(), ms(t), rate(t), ms(o), rate(o),
                  same ? "same" : "DIFFERS", ms(a), rate(a), static_cast<unsigned long long>(changed));
    b.markdown += line;
    std::fputs(line, stdout);
    std::fflush(stdout);
  }
}

void pruning_table(const ConfigFiles& config, const std::string& dir, LeaveOutBench& b) {
  b.markdown +=
      "\n## Simulator pruning (approx, wall time)\n\n"
      "Median of five renders each, alternating, each in its own process; `--no-prune` computes everything. "
      "Outputs must be equal but for `wall_s` and `left_out` (empty with `--no-prune`).\n\n"
      "| input | pruned wall s | --no-prune wall s | speed-up | same outputs | left out |\n|---|---|---|---|---|---|\n";
  for (const std::string& input : sample_workloads()) {
    const std::string base = dir + "/pruning/" + fs::path(input).filename().string();
    std::vector<double> pruned, full;
    nlohmann::json p, f;
    const bool ran = run_pairs(
        kPruneRuns, [&] { return !(p = render_in_child(input, "approx", base + "-pruned", config)).is_null(); },
        [&] { return !(f = render_in_child(input, "approx", base + "-all", config, {"--no-prune"})).is_null(); },
        [&] {
          pruned.push_back(p.at("wall_s"));
          full.push_back(f.at("wall_s"));
        });
    if (!ran) {
      ++b.failures;
      b.markdown += "| " + input + " | render failed |\n";
      continue;
    }
    const bool same = without_wall(p) == without_wall(f) && f.at("left_out").empty();
    b.failures += !same;
    std::string units;
    for (const nlohmann::json& l : p.at("left_out")) units += (units.empty() ? "" : ", ") + l.at("unit").get<std::string>();
    const double mp = median(pruned), mf = median(full);
    b.pruning.push_back({{"input", input}, {"pruned_wall_s", mp}, {"no_prune_wall_s", mf},
                         {"speedup", mp > 0 ? mf / mp : 0}, {"same_outputs", same}, {"left_out", p.at("left_out")}});
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %.3f | %.3f | %.2fx | %s | %s |\n", fs::path(input).filename().c_str(),
                  mp, mf, mp > 0 ? mf / mp : 0, same ? "yes" : "NO", units.empty() ? "—" : units.c_str());
    b.markdown += line;
    std::fputs(line, stdout);
    std::fflush(stdout);
  }
}

// Pruning may skip work but must charge what the hardware spends, so no
// pruning makes a run faster than one with the pruned work not there at
// all: the out-of-view objects culled (culling.objects, a change to the
// modeled hardware used here only as that bound) against --no-prune.
void pruning_ceiling(const ConfigFiles& config, const std::string& dir, LeaveOutBench& b) {
  ConfigFiles culled = config;
  culled.push_back(dir + "/objects_only.json");  // written by culling_table
  const std::string base = dir + "/pruning/ceiling";
  std::vector<double> ratio, without, full;
  bool same = true;  // object culling leaves the frame as it was
  nlohmann::json f, c;
  auto timed = [](const nlohmann::json& r) { return !r.is_null() && r.at("wall_s").get<double>() > 0; };
  const bool ran = run_pairs(
      kCeilingPairs, [&] { return timed(f = render_in_child(kOutOfView, "approx", base + "-all", config, {"--no-prune"})); },
      [&] { return timed(c = render_in_child(kOutOfView, "approx", base + "-culled", culled, {"--no-prune"})); },
      [&] {
        same = same && f.at("image_sha256") == c.at("image_sha256");
        full.push_back(f.at("wall_s"));
        without.push_back(c.at("wall_s"));
        ratio.push_back(full.back() / without.back());
      });
  if (!ran) {
    ++b.failures;
    b.markdown += std::string("\nThe pruning ceiling: a render of ") + kOutOfView + " failed.\n";
    return;
  }
  const double r = median(ratio);
  b.failures += !same;
  b.pruning_ceiling = {{"input", kOutOfView}, {"pairs", kCeilingPairs}, {"no_prune_wall_s", median(full)},
                       {"objects_culled_wall_s", median(without)}, {"ceiling", r}, {"same_frame", same}};
  char text[768];
  std::snprintf(text, sizeof text,
                "\nThe most that leaving out the out-of-view objects' work could save on `%s`: those objects not "
                "simulated at all (`culling.objects`, a change to the modeled hardware, used here only as that "
                "bound; both runs `--no-prune`) %.3f s against %.3f s, a ratio of %.2fx (median over %d pairs; "
                "the frame %s).\n",
                kOutOfView, median(without), median(full), r, kCeilingPairs, same ? "the same" : "DIFFERS");
  b.markdown += text;
  std::fputs(text, stdout);
}

}  // namespace

LeaveOutBench run_leave_out_bench(const ConfigFiles& config, const std::string& out_dir) {
  LeaveOutBench b;
  const std::string dir = out_dir + "/leave_out";
  fs::create_directories(dir);
  culling_table(config, dir, b);
  pruning_table(config, dir, b);
  pruning_ceiling(config, dir, b);
  return b;
}

}  // namespace girtd
