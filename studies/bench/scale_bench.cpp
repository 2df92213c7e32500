#include "bench/scale_bench.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <utility>

#include "bench/bench_stats.hpp"
#include "bench/user_render.hpp"
#include "io/json_file.hpp"
#include "io/subprocess.hpp"
#include "io/text_format.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

// The bars (docs: "Real sizes"): at the largest size golden within
// these multiples of assimp's import, approx within kApproxOverGolden of
// golden; the growth exponents at most kMaxExponent.
constexpr double kGoldenOverAssimpTime = 3.0, kGoldenOverAssimpMemory = 2.0, kApproxOverGolden = 2.0;
constexpr double kMaxExponent = 1.1;

std::string mesh_path(const std::string& out_dir, long n) { return out_dir + "/scale/sphere_" + std::to_string(n) + ".obj"; }

struct Sample {
  std::vector<double> elapsed, peak, wall;
};

// Least-squares slope of log y against log x.
double exponent(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = double(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  const double d = n * sxx - sx * sx;
  return d > 0 ? (n * sxy - sx * sy) / d : 0;
}

}  // namespace

std::vector<std::string> scale_bench_plan_lines(const std::string& out_dir, const std::vector<long>& sizes) {
  std::vector<std::string> lines;
  for (long n : sizes) lines.push_back("mesh\t" + std::to_string(n) + "\t" + mesh_path(out_dir, n));
  return lines;
}

ScaleBench run_scale_bench(const std::string& out_dir, const std::vector<long>& sizes, int runs) {
  ScaleBench b;
  const std::string dir = out_dir + "/scale";
  fs::create_directories(dir);
  const std::string self = self_executable();
  const std::string yardstick = (fs::path(self).parent_path() / "girtd_assimp_import").string();
  const std::string render = user_render_program();
  auto fail = [&b](const std::string& what) {
    std::fprintf(stderr, "\nbench: %s\n", what.c_str());
    ++b.failures;
    b.markdown += "\n" + what + "\n";
  };
  std::vector<double> tris, golden_t, golden_m, approx_t, approx_m, assimp_t, assimp_m;
  double last_time_ratio = 0, last_memory_ratio = 0, last_approx_ratio = 0;
  b.rows = nlohmann::json::array();
  for (long n : sizes) {
    const std::string mesh = mesh_path(out_dir, n);
    if (!fs::exists(mesh)) {
      fail("the mesh " + mesh + " is not there: tools/girtd bench --scale makes it first (tools/make_mesh.py)");
      return b;
    }
    Sample assimp, golden, approx;
    std::vector<double> time_ratio, memory_ratio, approx_ratio;
    long triangles = 0;
    const std::string log = dir + "/runs.log", counted = dir + "/assimp_faces.txt";
    const bool tty = isatty(STDERR_FILENO);
    for (int r = 0; r < runs; ++r) {
      if (tty) std::fprintf(stderr, "\r[girtd] bench --scale: %ld triangles, run %d/%d   ", n, r + 1, runs);
      fs::remove(counted);
      const ProcessUsage a = run_process_measured({yardstick, mesh}, counted);
      long assimp_faces = -1;
      if (std::ifstream in(counted); !(in >> assimp_faces)) assimp_faces = -1;
      double t[2], m[2];
      bool ok = a.exit_code == 0;
      for (int k = 0; k < 2 && ok; ++k) {
        const std::string backend = k == 0 ? "golden" : "approx";
        const std::string out = dir + "/" + backend + "_" + std::to_string(n);
        const ProcessUsage u =
            run_process_measured({render, "render", mesh, "--backend", backend, "--out", out, "--quiet"}, log);
        ok = u.exit_code == 0;
        if (!ok) break;
        const nlohmann::json report = read_json_file(out + "/report.json");
        triangles = report.at("frontend").at("polygons").get<long>();
        if (triangles != assimp_faces) {  // the same file read alike, or the comparison means nothing
          fail(mesh + ": " + backend + " read " + std::to_string(triangles) + " polygons, assimp alone " +
               std::to_string(assimp_faces));
          return b;
        }
        Sample& s = k == 0 ? golden : approx;
        s.elapsed.push_back(u.elapsed_s);
        s.peak.push_back(u.peak_rss_mb);
        s.wall.push_back(report.at("wall_s").get<double>());
        t[k] = u.elapsed_s;
        m[k] = u.peak_rss_mb;
      }
      if (!ok) {
        fail("a run on " + mesh + " failed (" + log + ")");
        return b;
      }
      assimp.elapsed.push_back(a.elapsed_s);
      assimp.peak.push_back(a.peak_rss_mb);
      time_ratio.push_back(t[0] / a.elapsed_s);
      memory_ratio.push_back(m[0] / a.peak_rss_mb);
      approx_ratio.push_back(t[1] / t[0]);
    }
    if (tty) std::fprintf(stderr, "\n");
    tris.push_back(double(triangles));
    assimp_t.push_back(median(assimp.elapsed));
    assimp_m.push_back(median(assimp.peak));
    golden_t.push_back(median(golden.elapsed));
    golden_m.push_back(median(golden.peak));
    approx_t.push_back(median(approx.elapsed));
    approx_m.push_back(median(approx.peak));
    last_time_ratio = median(time_ratio);
    last_memory_ratio = median(memory_ratio);
    last_approx_ratio = median(approx_ratio);
    b.rows.push_back({{"triangles", triangles},
                      {"mesh_mb", double(fs::file_size(mesh)) / (1024.0 * 1024.0)},
                      {"assimp", {{"elapsed_s", assimp_t.back()}, {"peak_mb", assimp_m.back()}}},
                      {"golden",
                       {{"elapsed_s", golden_t.back()}, {"peak_mb", golden_m.back()}, {"wall_s", median(golden.wall)}}},
                      {"approx",
                       {{"elapsed_s", approx_t.back()}, {"peak_mb", approx_m.back()}, {"wall_s", median(approx.wall)}}},
                      {"golden_over_assimp_time", last_time_ratio},
                      {"golden_over_assimp_memory", last_memory_ratio},
                      {"approx_over_golden_time", last_approx_ratio}});
  }
  // Over every size, and over the two largest alone: the fixed costs of a
  // run (start-up, the driver's build check) weigh on the small sizes and
  // flatten the fit over all of them.
  auto fit = [&](const std::vector<double>& y, bool last_two) -> nlohmann::json {
    if (tris.size() < 2) return nullptr;
    const size_t from = last_two ? tris.size() - 2 : 0;
    return exponent({tris.begin() + long(from), tris.end()}, {y.begin() + long(from), y.end()});
  };
  nlohmann::json fits, largest;
  for (const auto& [name, y] : std::vector<std::pair<std::string, const std::vector<double>*>>{
           {"golden_time", &golden_t}, {"golden_memory", &golden_m}, {"approx_time", &approx_t},
           {"approx_memory", &approx_m}, {"assimp_time", &assimp_t}, {"assimp_memory", &assimp_m}}) {
    fits[name] = fit(*y, false);
    largest[name] = fit(*y, true);
  }
  b.rows = {{"sizes", b.rows}, {"exponents", fits}, {"exponents_two_largest", largest}, {"runs", runs},
            {"timed", user_render_name()}};

  std::string& md = b.markdown;
  md += "\n## The simulator at scale: generated UV spheres, " + std::to_string(runs) + " runs each\n\n";
  md += std::string("Each run, in turn: assimp's import alone (`girtd_assimp_import`: `ReadFile` with no post-processing), then `") +
        user_render_name() +
        " FILE --backend golden`, then the same on approx, each in its own process. Elapsed: start to exit; peak: "
        "the largest process's resident memory (the simulator or its import child; the child has ended before the "
        "simulator's own peak, after the import). Medians over the runs; the ratios are the medians of each run's "
        "ratio.\n\n";
  md += "| triangles | OBJ MB | assimp s | assimp MB | golden s | golden MB | golden wall_s | golden us/triangle | approx s | "
        "approx MB | approx wall_s | golden / assimp time | golden / assimp memory | approx / golden time |\n";
  md += "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (size_t i = 0; i < tris.size(); ++i) {
    const nlohmann::json& r = b.rows["sizes"][i];
    md += "| " + std::to_string(long(tris[i])) + " | " + format_numbers("%.1f", r["mesh_mb"].get<double>()) + " | " +
          format_numbers("%.2f", assimp_t[i]) + " | " + format_numbers("%.0f", assimp_m[i]) + " | " + format_numbers("%.2f", golden_t[i]) + " | " +
          format_numbers("%.0f", golden_m[i]) + " | " + format_numbers("%.2f", r["golden"]["wall_s"].get<double>()) + " | " +
          format_numbers("%.2f", 1e6 * golden_t[i] / tris[i]) + " | " + format_numbers("%.2f", approx_t[i]) + " | " +
          format_numbers("%.0f", approx_m[i]) + " | " + format_numbers("%.2f", r["approx"]["wall_s"].get<double>()) + " | " +
          format_numbers("%.2f", r["golden_over_assimp_time"].get<double>()) + " | " +
          format_numbers("%.2f", r["golden_over_assimp_memory"].get<double>()) + " | " +
          format_numbers("%.2f", r["approx_over_golden_time"].get<double>()) + " |\n";
  }
  double worst = 0;
  if (tris.size() >= 2) {
    md += "\nGrowth exponents (the slope of log cost against log triangles), least squares over every size / between "
          "the two largest:\n\n| | golden time | golden memory | approx time | approx memory | assimp time | assimp memory |\n"
          "|---|---|---|---|---|---|---|\n";
    for (const auto* f : {&fits, &largest}) {
      md += f == &fits ? "| every size |" : "| two largest |";
      for (const char* k : {"golden_time", "golden_memory", "approx_time", "approx_memory", "assimp_time", "assimp_memory"}) {
        md += " " + format_numbers("%.2f", (*f)[k].get<double>()) + " |";
        if (std::string(k).rfind("assimp", 0) != 0) worst = std::max(worst, (*f)[k].get<double>());
      }
      md += "\n";
    }
  }
  if (!tris.empty()) {
    md += "\nAt " + std::to_string(long(tris.back())) + " triangles, against the bars (met: the median at least 10 % past the bar):\n\n";
    md += "| bar | measured | verdict |\n|---|---|---|\n";
    md += "| golden time at most " + format_numbers("%.0f", kGoldenOverAssimpTime) + "x assimp's | " + format_numbers("%.2fx", last_time_ratio) +
          " | " + bar_verdict(last_time_ratio, kGoldenOverAssimpTime) + " |\n";
    md += "| golden peak memory at most " + format_numbers("%.0f", kGoldenOverAssimpMemory) + "x assimp's | " +
          format_numbers("%.2fx", last_memory_ratio) + " | " + bar_verdict(last_memory_ratio, kGoldenOverAssimpMemory) + " |\n";
    md += "| approx time at most " + format_numbers("%.0f", kApproxOverGolden) + "x golden's | " + format_numbers("%.2fx", last_approx_ratio) +
          " | " + bar_verdict(last_approx_ratio, kApproxOverGolden) + " |\n";
    if (tris.size() >= 2)
      md += "| growth exponents at most " + format_numbers("%.1f", kMaxExponent) + " | " + format_numbers("%.2f", worst) +
            " (the largest of golden's and approx's, either fit) | " +
            (worst <= kMaxExponent ? "met" : "not met") + " |\n";
  }
  return b;
}

}  // namespace girtd
