// girtd stress: generated extreme cases (studies/stress/stress_cases) on
// reference, golden and rtl, each `render` in its own process (a crash or a
// hang is a verdict, not the end of the run), judged by
// studies/stress/stress_judge.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "stress/stress_command.hpp"
#include "io/output_set.hpp"
#include "common/input_error.hpp"
#include "io/json_file.hpp"
#include "io/png_io.hpp"
#include "io/subprocess.hpp"
#include "backends/front_end_runner.hpp"
#include "io/scene_reader.hpp"
#include "io/trace_reader.hpp"
#include "stress/stress_cases.hpp"
#include "stress/stress_judge.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

struct CaseResult {
  StressJudgement j;
  uint64_t seams = 0, wraps = 0;
  double wall_s = 0;
};

std::string first_line(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) return line;
  return "(no output)";
}

// One render in a child; "" on success, else what went wrong.
std::string render_child(const std::string& input, const std::string& backend, const std::string& dir,
                         const ConfigFiles& config, double timeout_s, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {self_executable(), "render", input, "--backend", backend, "--out", dir, "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  for (const std::string& c : config_args(config)) args.push_back(c);
  const std::string log = dir + ".log";
  std::remove(log.c_str());
  const int rc = run_process_timed(args, log, timeout_s);
  if (rc == 0) return "";
  if (rc == kTimedOut) return backend + ": no result within " + std::to_string(int(timeout_s)) + " s (a hang)";
  if (rc == kStopped) return backend + ": stopped by a signal";
  if (rc < 0) return backend + ": crashed: " + first_line(log);
  return backend + ": exit " + std::to_string(rc) + ": " + first_line(log);
}

CaseResult run_case(const StressCase& c, const std::string& dir, const ConfigFiles& config, const Params& params,
                    double timeout_s) {
  CaseResult r;
  const auto start = std::chrono::steady_clock::now();
  fs::create_directories(dir);
  const std::string input = dir + (c.scene ? "/case.json" : "/case.trace");
  std::ofstream(input) << c.text;
  auto fail = [&](const std::string& why) {
    r.j.verdict = StressVerdict::kFail;
    r.j.why = why;
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  };
  for (const char* b : {"reference", "golden", "rtl"})
    if (const std::string e = render_child(input, b, dir + "/" + b, config, timeout_s); !e.empty()) return fail(e);
  const nlohmann::json golden = read_json_file(dir + "/golden/report.json");
  for (size_t k = 0; k < c.reorders.size(); ++k) {  // order: every vertex order draws one picture
    const std::string v = dir + "/order_" + std::to_string(k + 1);
    std::ofstream(v + ".trace") << c.reorders[k];
    if (const std::string e = render_child(v + ".trace", "golden", v, config, timeout_s); !e.empty()) return fail(e);
    if (read_json_file(v + "/report.json").at("image_sha256") != golden.at("image_sha256"))
      return fail("vertex order " + std::to_string(k + 2) + " of 6 draws another picture");
  }
  // The triangles as drawn: a scene's from the front end, here in-process
  // (its dump may hold corners past the trace format's 1e6 px).
  const Trace drawn = c.scene ? run_front_end(read_scene(input, params), params, PrunePlan{}).triangles
                              : read_trace(input, std::nullopt, params);
  r.j = judge_stress_case(drawn, params, read_json_file(dir + "/reference/report.json"), golden,
                          read_json_file(dir + "/rtl/report.json"), read_png_rgb(dir + "/reference/frame.png"),
                          read_png_rgb(dir + "/golden/frame.png"));
  r.seams = golden.value("pixels_reblended", uint64_t{0});
  if (golden.at("numerics").is_object())
    for (const auto& [ep, counts] : golden.at("numerics").items())
      if (counts.is_object()) r.wraps += counts.value("wraps", uint64_t{0});
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

int run_stress(const StressArgs& a) {
  const Params params = Params::from_files(a.config);
  const std::vector<std::string>& families = a.families.empty() ? stress_families() : a.families;
  const std::string models_dir = fs::absolute("traces/models").string();
  std::vector<StressCase> cases;
  for (const std::string& f : families)
    for (StressCase& c : stress_cases(f, models_dir))
      if (!a.fast || c.fast) cases.push_back(std::move(c));
  if (!fs::exists(models_dir + "/cube.obj"))
    for (const StressCase& c : cases)
      if (c.scene) throw InputError(models_dir, 0, "the nearplane family's models are not here (run from the source tree)");

  const std::string work = a.out_dir + "/cases";
  std::ostringstream csv, md;
  csv << "family,case,verdict,beyond_budget,silent,affected_triangles,seams,wraps,wall_s,why\n";
  md << "| family | case | verdict | off budget | on counted triangles | seams | wraps | wall s | why |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
  int passed = 0, flagged = 0, failed = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const StressCase& c = cases[i];
    CaseResult r;
    try {
      r = run_case(c, work + "/" + c.name, a.config, params, a.timeout_s);
    } catch (const std::exception& e) {  // an unreadable render is this case's FAIL, not the run's end
      r.j.verdict = StressVerdict::kFail;
      r.j.why = std::string("reading the renders: ") + e.what();
    }
    const char* v = verdict_name(r.j.verdict);
    passed += r.j.verdict == StressVerdict::kExact;
    flagged += r.j.verdict == StressVerdict::kFlagged;
    failed += r.j.verdict == StressVerdict::kFail;
    std::fprintf(stderr, "[%zu/%zu] %-10s %-28s %-7s %s\n", i + 1, cases.size(), c.family.c_str(), c.name.c_str(), v,
                 r.j.why.c_str());
    char wall[32];
    std::snprintf(wall, sizeof wall, "%.2f", r.wall_s);
    std::string why_csv = r.j.why;
    for (char& ch : why_csv)
      if (ch == '"') ch = '\'';
    csv << c.family << "," << c.name << "," << v << "," << r.j.beyond_budget << "," << r.j.silent << ","
        << r.j.affected_triangles << "," << r.seams << "," << r.wraps << "," << wall << ",\"" << why_csv << "\"\n";
    md << "| " << c.family << " | " << c.what << " | " << v << " | " << r.j.beyond_budget << " | "
       << r.j.beyond_budget - r.j.silent << " | " << r.seams << " | " << r.wraps << " | " << wall << " | " << r.j.why
       << " |\n";
  }
  const StressBudget b = StressBudget::of(params);
  std::ostringstream head;
  head << "# girtd stress\n\nBudget against the reference (studies/stress/stress_judge.hpp): edges within " << b.edge_px
       << " px and fringes excused, depths within " << b.z_units << " units excused, elsewhere " << b.colour_lsb
       << " LSB per channel.\n\n";
  OutputSet out(a.out_dir);
  out.add_text("results.csv", csv.str());
  out.add_text("results.md", head.str() + md.str());
  out.commit();
  std::printf("%d passed, %d flagged, %d failed\n", passed, flagged, failed);
  return failed > 0 ? 1 : 0;
}

}  // namespace girtd
