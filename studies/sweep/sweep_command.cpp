// girtd sweep: a design-space sweep (docs/interface.md). Every point x input is a
// `girtd render` in its own process, run by a pool of local workers (or, with
// the driver's --slurm, a Slurm job array running `girtd sweep --slice I/S`);
// each row is kept in DIR/rows/ as it completes, so a rerun skips what is
// there and a killed sweep resumes. Then K points chosen from the spec's hash
// are rerun on rtl and the tables are written. What must exist first (RTL
// variants, the DDA's synthesised sizes, the array) plan_sweep tells the driver.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <set>
#include <thread>

#include "cli/child_render.hpp"
#include "sweep/sweep_command.hpp"
#include "io/output_set.hpp"
#include "common/file_text.hpp"
#include "common/input_error.hpp"
#include "io/input_reader.hpp"
#include "io/json_file.hpp"
#include "io/sha256.hpp"
#include "io/subprocess.hpp"
#include "sweep/sweep_points.hpp"
#include "engine/backend_registry.hpp"
#include "io/sweep_spec.hpp"
#include "sweep/sweep_table.hpp"
#include "sweep/dda_cells.hpp"
#include "rtl/rtl_variants.hpp"
#include "report/sweep_page.hpp"

namespace girtd {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

// A sweep stopped by SIGINT or SIGTERM (128 + SIGINT, as a shell reports it).
constexpr int kExitStopped = 130;

// Set by SIGINT / SIGTERM: the workers take no more rows, and a render that
// ends by a signal then was stopped, not crashed (its row is left for the rerun).
std::atomic<bool> g_stopping{false};
extern "C" void on_stop_signal(int) { g_stopping = true; }
// Set when a render exits for want of an RTL variant (said once).
std::atomic<bool> g_missing_variant{false};

struct Task {
  const SweepPoint* point;
  std::string input;
  std::string id;  // point-input
  bool repeat;     // a one-frame input, drawn spec.repeat times
};

// A row's file names its point, its input and how it ran (back end, frames):
// a rerun with another back end or repeat count does not take old rows.
std::string row_tag(const std::string& input, const SweepSpec& spec, bool repeat) {
  const std::string key = input + "|" + spec.backend + "|" + std::to_string(repeat ? spec.repeat : 1);
  return sha256_hex(key).substr(0, 8);
}

void write_json_atomically(const fs::path& p, const json& j) {
  const fs::path tmp = p.string() + ".tmp" + std::to_string(getpid());
  std::ofstream(tmp) << j.dump(2) << "\n";
  fs::rename(tmp, p);
}

json base_row(const Task& t) {
  json row = {{"point", t.point->id}, {"input", t.input}, {"valid", t.point->invalid.empty()}, {"rtl_agrees", nullptr}};
  for (const auto& [axis, v] : t.point->axis_values.items()) row[axis] = v;
  for (const ReportColumn& c : kReportColumns) row[c.name] = nullptr;
  if (!t.point->cost.is_null()) row.update(t.point->cost);
  if (!t.point->invalid.empty()) row["invalid"] = t.point->invalid;
  return row;
}

// The task's render on `backend` into `run` (its log beside it): the
// spec's base files and the point's, the frames the spec asks for.
json render_task(const Task& t, const SweepSpec& spec, const std::string& backend, const fs::path& run, int* rc) {
  ConfigFiles config = spec.base;
  config.push_back(t.point->config_file);
  std::vector<std::string> extra;
  if (t.repeat) extra = {"--repeat", std::to_string(spec.repeat)};
  return render_in_child(t.input, backend, run.string(), config, extra, run.string() + ".log", rc);
}

// One row: the point's render of the input; none when the render was
// killed (the sweep is being stopped: the row is left for the rerun).
std::optional<json> run_task(const Task& t, const SweepSpec& spec, const fs::path& dir) {
  json row = base_row(t);
  if (!t.point->invalid.empty()) return row;
  const fs::path run = dir / "runs" / t.id;
  int rc = 0;
  const json r = render_task(t, spec, spec.backend, run, &rc);
  // The same signal reaches this process and the child together: the child's
  // end may be seen before our handler has run.
  if (rc == kStopped || (rc < 0 && g_stopping)) {
    g_stopping = true;
    return std::nullopt;
  }
  // A render that found an RTL variant missing is not the point's verdict:
  // no row, so a run through the driver (which builds it) runs it again.
  if (rc == kExitMissingPrerequisite) {
    if (!g_missing_variant.exchange(true))
      std::fprintf(stderr, "girtd sweep: a render needs an RTL variant that is not built (%s.log): run the sweep "
                           "through tools/girtd, which builds it first\n", run.c_str());
    return std::nullopt;
  }
  if (r.is_null()) {
    row["valid"] = false;
    row["invalid"] = std::string(rc < 0 ? "the render crashed: " : "the render failed: ") + run.string() + ".log";
    return row;
  }
  for (const ReportColumn& c : kReportColumns) row[c.name] = r.value(json::json_pointer(c.pointer), json());
  fs::remove_all(run);  // the frame is not kept: its SHA is
  fs::remove(run.string() + ".log");
  return row;
}

class Progress {
 public:
  Progress(size_t total, size_t done) : total_(total), done_(done), start_done_(done), tty_(isatty(STDERR_FILENO)) {}
  void step() {
    std::lock_guard<std::mutex> lock(m_);
    ++done_;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const double eta = elapsed / double(done_ - start_done_) * double(total_ - done_);
    const int width = 30, filled = int(width * done_ / std::max<size_t>(total_, 1));
    if (tty_ || done_ == total_ || done_ * 20 / total_ != (done_ - 1) * 20 / total_)
      std::fprintf(stderr, "%s[sweep] [%s%s] %zu/%zu rows, %.0f s, ETA %.0f s%s", tty_ ? "\r" : "",
                   std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), done_, total_, elapsed,
                   eta, tty_ && done_ < total_ ? "" : "\n");
  }

 private:
  std::mutex m_;
  size_t total_, done_, start_done_;
  bool tty_;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

// Fisher-Yates over mt19937_64: the same order from every standard library.
template <class T>
void seeded_shuffle(std::vector<T>& v, uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[size_t(rng() % i)]);
}

// The points spot-checked on rtl: K of the valid ones, drawn by a generator
// seeded from the spec's hash (the same on every machine and under Slurm).
std::vector<const SweepPoint*> spot_check_points(const SweepSpec& spec, const std::vector<SweepPoint>& points) {
  const std::string text = read_file_text(spec.path).value_or("");
  const std::string spec_sha = sha256_hex(text);
  std::vector<const SweepPoint*> valid;
  for (const SweepPoint& p : points)
    if (p.invalid.empty()) valid.push_back(&p);
  // Stable: of points that merge to one design the first stays, the one its tasks name.
  std::stable_sort(valid.begin(), valid.end(), [](auto* a, auto* b) { return a->id < b->id; });
  valid.erase(std::unique(valid.begin(), valid.end(), [](auto* a, auto* b) { return a->id == b->id; }), valid.end());
  seeded_shuffle(valid, std::stoull(spec_sha.substr(0, 16), nullptr, 16));
  if (valid.size() > size_t(spec.spot_check)) valid.resize(size_t(spec.spot_check));
  return valid;
}

// rtl agrees: the same picture and modeled time within 0.1 %. A run that
// fails is no verdict: rtl_agrees stays null, the reason in rtl_error.
void spot_check(const Task& t, json& row, const SweepSpec& spec, const fs::path& dir) {
  const std::string& yardstick = backend_with(kExactTiming).name;
  const fs::path run = dir / "runs" / (t.id + "-" + yardstick);
  const json r = render_task(t, spec, yardstick, run, nullptr);
  if (r.is_null()) {
    row["rtl_error"] = "the rtl render failed: " + run.string() + ".log";
    return;
  }
  const double a = row["modeled_time_s"], b = r["modeled_time_s"];
  row["rtl_agrees"] = r["image_sha256"] == row["image_sha256"] && std::abs(a - b) <= 1e-3 * b;
  row["rtl_modeled_time_s"] = b;
  if (row["rtl_agrees"].get<bool>()) fs::remove_all(run);  // a disagreement keeps its evidence
  else row["rtl_run"] = run.string();
}


// What a sweep is made of, read and checked before anything runs.
struct SweepSetup {
  SweepSetup() = default;
  SweepSetup(SweepSetup&&) = default;  // a moved vector keeps its elements: Task::point stays valid
  SweepSetup(const SweepSetup&) = delete;  // a copy's tasks would point into the original
  SweepSetup& operator=(const SweepSetup&) = delete;
  SweepSpec spec;
  Params base;
  std::string out;
  std::vector<SweepPoint> points;
  std::vector<Task> tasks;
  std::vector<size_t> todo;  // this slice's tasks without a row yet
  int lock = -1;             // held while this process gathers in `out`
};

std::vector<std::string> timed_backends() {
  std::vector<std::string> timed;
  for (const BackendEntry& b : backend_registry())
    if (b.timed()) timed.push_back(b.name);
  return timed;
}

// Every input is read before anything runs (bad input: exit 2, nothing
// written); "repeat" draws one-frame inputs that many times, and an
// animation as it is. `warn`: say so (once: not again when planning).
SweepSetup prepare_sweep(const SweepArgs& a, size_t slice, size_t slices, bool warn) {
  SweepSetup s;
  s.spec = read_sweep_spec(a.spec, timed_backends());
  std::map<std::string, bool> repeat;
  s.base = Params::from_files(s.spec.base);
  for (const std::string& input : s.spec.inputs) {
    const size_t frames = open_input(input, std::nullopt, s.base).frames();
    repeat[input] = s.spec.repeat > 1 && frames == 1;
    if (s.spec.repeat > 1 && frames > 1 && warn)
      std::fprintf(stderr, "warning: %s: %zu frames: \"repeat\" draws one-frame inputs; this one runs as it is\n",
                   input.c_str(), frames);
  }
  s.out = a.out_dir.empty() ? "out/sweep/" + fs::path(a.spec).stem().string() : a.out_dir;
  check_output_dir(s.out, "--out");
  const fs::path dir(s.out);
  fs::create_directories(dir / "rows");
  // One gathering sweep per folder at a time (its Slurm tasks excepted).
  s.lock = a.slice.empty() ? open((dir / ".lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644) : -1;
  if (s.lock >= 0 && flock(s.lock, LOCK_EX | LOCK_NB) != 0)
    throw InputError("--out", 0, "another girtd sweep is running in " + s.out);
  s.points = sweep_points(s.spec, s.out);
  std::set<std::string> ids;  // two combinations can merge to one design: it runs once
  for (const SweepPoint& p : s.points)
    for (const std::string& input : s.spec.inputs) {
      const std::string id = p.id + "-" + row_tag(input, s.spec, repeat[input]);
      if (ids.insert(id).second) s.tasks.push_back({&p, input, id, repeat[input]});
    }
  for (size_t i = slice; i < s.tasks.size(); i += slices)
    if (!fs::exists(dir / "rows" / (s.tasks[i].id + ".json"))) s.todo.push_back(i);
  return s;
}

Params point_params(const SweepSpec& spec, const SweepPoint& p) {
  ConfigFiles files = spec.base;
  files.push_back(p.config_file);
  return Params::from_files(files);
}

}  // namespace

std::vector<std::string> plan_sweep(const SweepArgs& a) {
  const SweepSetup s = prepare_sweep(a, 0, 1, false);
  std::vector<std::string> lines;
  std::set<std::string> seen;
  auto add = [&](const std::string& line) {
    if (seen.insert(line).second) lines.push_back(line);
  };
  const std::string points_dir = (fs::path(s.out) / "points").string();
  const bool all_on_rtl = backend_named(s.spec.backend).has(kRunsRtl);
  std::set<const SweepPoint*> on_rtl;
  if (!all_on_rtl && s.spec.spot_check > 0 && !backend_named(s.spec.backend).has(kExactTiming))
    for (const SweepPoint* p : spot_check_points(s.spec, s.points)) on_rtl.insert(p);
  for (const SweepPoint& p : s.points) {
    if (!p.invalid.empty()) continue;
    const Params params = point_params(s.spec, p);
    if (const auto request = dda_cells_request(params, points_dir)) add("dda-cells\t" + *request);
    if (all_on_rtl || on_rtl.count(&p))
      if (const auto v = needed_rtl_variant(params)) add(rtl_variant_plan_line(*v, params));
  }
  if (a.slurm && !s.todo.empty()) {
    const size_t slices = std::min<size_t>(s.todo.size(), a.jobs > 0 ? size_t(a.jobs) : 64);
    add("slurm-array\t" + std::to_string(slices) + "\t" + a.spec + "\t" + s.out);
  }
  add("plots\t" + s.out);
  return lines;
}

int run_sweep(const SweepArgs& a) {
  if (a.slurm)
    throw InputError("--slurm", 0, "the driver submits the Slurm array: run tools/girtd sweep " + a.spec + " --slurm");
  size_t slice = 0, slices = 1;
  if (!a.slice.empty() && std::sscanf(a.slice.c_str(), "%zu/%zu", &slice, &slices) != 2)
    throw InputError("--slice", 0, "expected I/S, got '" + a.slice + "'");
  if (slices == 0 || slice >= slices) throw InputError("--slice", 0, "I must lie in 0 .. S - 1");
  SweepSetup s = prepare_sweep(a, slice, slices, a.slice.empty());
  const SweepSpec& spec = s.spec;
  const std::string& out = s.out;
  const fs::path dir(out);
  const std::vector<SweepPoint>& points = s.points;
  const std::vector<Task>& tasks = s.tasks;
  std::vector<size_t>& todo = s.todo;
  std::printf("girtd sweep: %zu points x %zu inputs = %zu rows on %s; %zu already in %s\n", points.size(),
              spec.inputs.size(), tasks.size(), spec.backend.c_str(), tasks.size() - todo.size(), out.c_str());
  std::fflush(stdout);
  Progress progress(tasks.size(), tasks.size() - todo.size());
  std::atomic<size_t> next{0};
  struct sigaction stop_action {};
  stop_action.sa_handler = on_stop_signal;
  sigaction(SIGINT, &stop_action, nullptr);
  sigaction(SIGTERM, &stop_action, nullptr);
  auto worker = [&] {
    for (size_t k; !g_stopping && (k = next++) < todo.size();) {
      const Task& t = tasks[todo[k]];
      std::optional<json> row;
      try {
        row = run_task(t, spec, dir);
      } catch (const std::exception& e) {  // a row, not the end of the sweep
        row = base_row(t);
        (*row)["valid"] = false;
        (*row)["invalid"] = std::string("the render's outputs could not be read: ") + e.what();
      }
      if (row) {
        write_json_atomically(dir / "rows" / (t.id + ".json"), *row);
        progress.step();
      }
    }
  };
  const int jobs = a.jobs > 0 ? a.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int i = 0; i < std::min<int>(jobs, int(todo.size())); ++i) pool.emplace_back(worker);
  for (std::thread& th : pool) th.join();
  if (!a.slice.empty()) return 0;  // a Slurm task: the gathering process writes the tables
  size_t missing = 0;
  for (const Task& t : tasks) missing += !fs::exists(dir / "rows" / (t.id + ".json"));
  if (g_stopping) {
    std::printf("\nstopped: %zu row(s) not run; run the sweep again to finish it\n", missing);
    return kExitStopped;
  }
  if (missing) {
    std::printf("\n%zu row(s) not run; run the sweep again to finish it\n", missing);
    return 1;
  }

  // Spot checks on rtl, kept in the rows as they finish (a rerun skips them).
  int disagreements = 0;
  if (spec.spot_check > 0 && backend_named(spec.backend).has(kExactTiming))
    std::printf("spot_check: the sweep ran on %s already; nothing to check\n", spec.backend.c_str());
  else if (spec.spot_check > 0) {
    const auto checked = spot_check_points(spec, points);
    std::printf("spot-checking %zu point(s) on rtl\n", checked.size());
    for (const SweepPoint* p : checked)
      for (const Task& t : tasks) {
        if (t.point != p) continue;
        const fs::path file = dir / "rows" / (t.id + ".json");
        json row = read_json_file(file);
        if (row["rtl_agrees"].is_null() && row["valid"].get<bool>()) {
          spot_check(t, row, spec, dir);
          write_json_atomically(file, row);
        }
        if (row.contains("rtl_error")) std::printf("spot check: %s\n", row["rtl_error"].get<std::string>().c_str());
        if (row["rtl_agrees"] == false) {
          ++disagreements;
          std::printf("rtl DISAGREES on point %s, %s\n", p->id.c_str(), t.input.c_str());
        }
      }
  }

  json rows = json::array();
  for (const Task& t : tasks) {
    json row = read_json_file(dir / "rows" / (t.id + ".json"));
    const json now = base_row(t);  // this spec's axis names and cost model over a kept row's
    for (const std::string& k : {std::string("point"), std::string("input")}) row[k] = now[k];
    for (const auto& [k, v] : t.point->axis_values.items()) row[k] = v;
    if (!t.point->cost.is_null()) row.update(t.point->cost);
    rows.push_back(row);
  }
  std::vector<std::string> axes;
  for (const SweepAxis& ax : spec.axes) axes.push_back(ax.name);
  const SweepSummary summary = summarize_sweep(rows, axes, spec.inputs.size());
  size_t unsized = 0;
  for (const SweepPoint& p : points) unsized += p.invalid.empty() && p.cost["cost_yosys_dda_cells"].is_null();
  if (unsized)
    std::fprintf(stderr, "warning: %zu point(s) without cost_yosys_dda_cells: tools/girtd sweep sizes the DDA by "
                         "synthesis first (yosys: tools/girtd hw-cost installs it)\n", unsized);
  OutputSet files(out);
  files.add_text("results.json", json{{"spec", a.spec}, {"backend", spec.backend}, {"repeat", spec.repeat},
                                      {"target_mpixels_per_s", s.base.target_mpixels_per_s},
                                      {"axes", axes}, {"rows", rows}, {"points", summary.points}}
                                      .dump(2) + "\n");
  files.add_text("results.csv", sweep_csv(rows, axes));
  files.add_text("sweep.md", "# girtd sweep " + a.spec + "\n\n" + summary.markdown);
  const std::optional<ChartLibrary> charts = load_chart_library();
  if (!charts) std::fprintf(stderr, "warning: sweep.html: %s\n", kNoChartLibrary);
  files.add_text("sweep.html", sweep_html(a.spec, summary.headline, summary.points, axes, s.base.target_mpixels_per_s, charts));
  files.commit();
  std::fputs(summary.headline.c_str(), stdout);
  std::printf("wrote %s, results.csv, sweep.md, sweep.html\n", files.path("results.json").c_str());
  if (disagreements) std::printf("%d spot check(s) disagree with rtl\n", disagreements);
  return disagreements ? 1 : 0;
}

}  // namespace girtd
