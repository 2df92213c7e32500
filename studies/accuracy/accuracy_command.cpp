// girtd accuracy: error against run time (docs/interface.md). Every input x
// variant x level is a `girtd render` in its own process; the reference
// back end's frame is each row's picture yardstick, Mesa llvmpipe a second
// one for opaque Q = 0 triangle-level inputs, rtl each row's timing one.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "report/accuracy_page.hpp"
#include "accuracy/accuracy_levels.hpp"
#include "accuracy/accuracy_table.hpp"
#include "engine/backend_registry.hpp"
#include "accuracy/config_variants.hpp"
#include "accuracy/llvmpipe_render.hpp"
#include "claims/ep_precision.hpp"
#include "cli/child_render.hpp"
#include "rtl/rtl_variants.hpp"
#include "accuracy/accuracy_command.hpp"
#include "io/output_set.hpp"
#include "common/input_error.hpp"
#include "io/image_compare.hpp"
#include "io/png_io.hpp"
#include "io/input_reader.hpp"
#include "io/trace_reader.hpp"
#include "io/workload_list.hpp"

namespace girtd {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr const char* kDefaultInputs = "traces/accuracy_inputs.txt";

struct Frame {
  RgbImage rgb;
  std::vector<uint16_t> z;
};

Frame read_frame(const std::string& dir) {
  Frame f;
  f.rgb = read_png_rgb(dir + "/frame.png");
  int w = 0, h = 0;
  f.z = read_png_gray16(dir + "/z.png", w, h);
  return f;
}

// The llvmpipe yardstick applies to opaque, Q = 0, full-window triangle
// traces; it draws the last frame. OSMesa failing is a warning, not the end.
std::optional<Frame> llvmpipe_frame(const std::string& input, const Params& params) {
  if (!has_trace_header(input) || header_level(input) != TraceLevel::kTriangle) return std::nullopt;
  const Trace trace = read_trace(input, std::nullopt, params);
  const Window full{0, 0, params.screen_width - 1, params.screen_height - 1};
  for (const TraceFrame& f : trace.frames) {
    if (f.settings.q != 0 || f.settings.window.x0 != full.x0 || f.settings.window.y0 != full.y0 ||
        f.settings.window.x1 != full.x1 || f.settings.window.y1 != full.y1)
      return std::nullopt;
    for (const Triangle& t : f.triangles)
      for (const Vertex& v : t.v)
        if (v.t < 1) return std::nullopt;
  }
  if (trace.frames.empty()) return std::nullopt;
  const TraceFrame& last = trace.frames.back();
  try {
    LlvmpipeFrame l = render_llvmpipe(last.triangles, params.screen_width, params.screen_height,
                                      last.settings.background, static_cast<uint16_t>(params.depth_clear));
    return Frame{std::move(l.rgb), std::move(l.z)};
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "warning: %s: no llvmpipe column: %s\n", input.c_str(), e.what());
    return std::nullopt;
  }
}

json picture_error(const Frame& a, const Frame& b, uint16_t z_clear) {
  return picture_error_cell(compare_images(a.rgb, b.rgb), compare_depth(a.z, b.z, z_clear));
}

json opt_number(const json& report, const char* key) {
  return report.contains(key) && !report[key].is_null() ? report[key] : json();
}

// What the per-counter table compares with rtl.
json counters_of(const json& report) {
  json c = {{"dda_cycles", opt_number(report, "dda_cycles")}};
  if (report.contains("dda_states") && report["dda_states"].is_object())
    for (const auto& [state, clocks] : report["dda_states"].items()) c["dda_clocks." + state] = clocks;
  if (report.contains("cache") && report["cache"].is_object()) c["page_misses"] = report["cache"]["page_misses"];
  if (report.contains("stages") && report["stages"].contains("had")) c["had_busy_s"] = report["stages"]["had"]["busy_s"];
  return c;
}

json relative_differences(const json& counters, const json& rtl) {
  json out = json::object();
  for (const auto& [k, v] : rtl.items()) {
    if (v.is_null() || !counters.contains(k) || counters[k].is_null()) {
      out[k] = nullptr;
      continue;
    }
    // relative to rtl's; absolute where rtl's is 0
    const double r = v.get<double>(), x = counters[k].get<double>();
    out[k] = (x - r) / (r != 0 ? std::abs(r) : 1.0);
  }
  return out;
}

// What a variant's formats cost and how far its EPs drift (the precision
// sweep's columns): the thesis' error measure after 1,024 and 2,048 steps
// (claims/ep_precision.hpp) and the bits of the EPs' registers (value,
// d/dx, d/dy, AUX: four per EP) and adders.
json variant_formats(const Params& p) {
  json errors = json::object();
  int register_bits = 0, adder_bits = 0;
  for (EpKind ep : kEpKinds) {
    Params q = p;
    const FixFormat& f = ep_format(q, ep);
    errors[ep_key(ep)] = {{"frac_bits", f.frac_bits},
                          {"unit", ep_unit(ep)},
                          {"after_1024", ep_error_after_steps(p, ep, kAcrossSteps)},
                          {"after_2048", ep_error_after_steps(p, ep, kCornerSteps)},
                          {"bound_1024", ep_bound(ep, f.frac_bits)}};
    const int count = ep == EpKind::kColor || ep == EpKind::kD ? 3 : 1;  // R, G, B; D1..D3
    register_bits += 4 * count * f.total_bits();
    adder_bits += count * f.total_bits();
  }
  return {{"ep_error", errors}, {"register_bits", register_bits}, {"adder_bits", adder_bits}};
}

std::string slug(const std::string& s) {
  std::string out;
  for (char c : s) out += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
  return out;
}

std::vector<AccuracyLevel> chosen_levels(const AccuracyArgs& a) {
  const std::string& exact = backend_with(kExactPicture).name;
  std::vector<AccuracyLevel> levels = {accuracy_level(exact, backend_registry())};  // the picture yardstick, run first
  for (const std::string& name : a.levels.empty() ? default_accuracy_levels(backend_registry()) : a.levels)
    if (name != exact) levels.push_back(accuracy_level(name, backend_registry()));
  return levels;
}

// A variant's configuration files: the run's, and its override written
// under DIR/configs/ (the base variant has none).
ConfigFiles variant_config(const AccuracyArgs& a, const ConfigVariant& variant) {
  ConfigFiles config = a.config;
  if (variant.label != "base") {
    const fs::path file = fs::path(a.out_dir) / "configs" / (slug(variant.label) + ".json");
    fs::create_directories(file.parent_path());
    std::ofstream(file) << variant.override_json().dump(2) << "\n";
    config.push_back(file.string());
  }
  return config;
}

}  // namespace

std::vector<std::string> plan_accuracy(const AccuracyArgs& a) {
  std::vector<std::string> lines;
  bool runs_rtl = false;
  for (const AccuracyLevel& level : chosen_levels(a)) runs_rtl |= backend_named(level.backend).has(kRunsRtl);
  if (runs_rtl)
    for (const ConfigVariant& variant : config_variants(a.vary)) {
      std::optional<Params> params;
      try {
        params = load_params(variant_config(a, variant));
      } catch (const InputError&) {
        continue;  // an invalid variant is a row, not a run
      }
      if (const auto v = needed_rtl_variant(*params)) {
        const std::string line = rtl_variant_plan_line(*v, *params);
        if (std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
      }
    }
  lines.push_back("plots\t" + a.out_dir);
  return lines;
}

int run_accuracy(const AccuracyArgs& a) {
  const std::vector<std::string> inputs = a.inputs.empty() ? read_input_list(kDefaultInputs) : a.inputs;
  const std::string& exact = backend_with(kExactPicture).name, &yardstick = backend_with(kExactTiming).name;
  const std::vector<AccuracyLevel> levels = chosen_levels(a);
  const std::vector<ConfigVariant> variants = config_variants(a.vary);
  // Bad usage and bad input are found before anything runs or is written.
  const Params base_params = load_params(a.config);
  for (const std::string& input : inputs) open_input(input, std::nullopt, base_params);

  const fs::path runs = fs::path(a.out_dir) / "runs";
  fs::create_directories(runs);
  json rows = json::array();
  json variant_table = json::array();
  const size_t total = inputs.size() * variants.size() * levels.size();
  size_t done = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (const ConfigVariant& variant : variants) {
    const ConfigFiles config = variant_config(a, variant);
    std::optional<std::string> invalid;
    std::optional<Params> params;
    try {
      params = load_params(config);
    } catch (const InputError& e) {
      invalid = e.formatted();
    }
    json vt = {{"variant", variant.label}, {"settings", variant.settings}};
    if (params) vt.update(variant_formats(*params));
    else vt["invalid"] = *invalid;
    variant_table.push_back(vt);
    for (const std::string& input : inputs) {
      const fs::path base = runs / slug(fs::path(input).filename().string()) / slug(variant.label);
      std::optional<Frame> reference, llvmpipe;
      if (params && !invalid) llvmpipe = llvmpipe_frame(input, *params);
      std::optional<double> rtl_time;
      json rtl_counters;
      const size_t first_row = rows.size();
      for (const AccuracyLevel& level : levels) {
        json row = {{"input", input}, {"level", level.name}, {"variant", variant.label}, {"settings", variant.settings},
                    {"complete", level.draws_frame}};
        for (const char* key : {"wall_s", "sim_pixels_per_s", "dda_clocks_per_s", "modeled_time_s", "time_error",
                                "image", "llvmpipe"})
          row[key] = nullptr;  // every row has the contract's columns
        ++done;
        if (invalid) {
          row["invalid"] = *invalid;
          rows.push_back(row);
          continue;
        }
        const std::string dir = (base / level.name).string();
        std::vector<std::string> extra = level.render_args;
        extra.push_back("--z-png");
        const json report = render_in_child(input, level.backend, dir, config, extra, dir + ".log");
        if (report.is_null()) {
          row["invalid"] = "the render failed: " + dir + ".log";
          std::fprintf(stderr, "girtd accuracy: %s on %s (%s) failed, see %s.log\n", input.c_str(), level.name.c_str(),
                       variant.label.c_str(), dir.c_str());
          rows.push_back(row);
          continue;
        }
        const double wall = report["wall_s"];
        const std::optional<double> modeled = level_modeled_time(level, report);
        row["wall_s"] = wall;
        // Rates of the simulator over what it drew: a sampled run draws a part (null).
        if (level.draws_frame && wall > 0) {
          row["sim_pixels_per_s"] = report["pixels_generated"].get<double>() / wall;
          if (!report["dda_cycles"].is_null()) row["dda_clocks_per_s"] = report["dda_cycles"].get<double>() / wall;
        }
        row["modeled_time_s"] = modeled ? json(*modeled) : json();
        row["image_sha256"] = report["image_sha256"];
        if (!report["sampling"].is_null()) row["time_ci_half_s"] = report["sampling"]["ci_half_s"];
        row["counters"] = counters_of(report);
        if (level.draws_frame) {
          const Frame frame = read_frame(dir);
          const uint16_t z_clear = static_cast<uint16_t>(params->depth_clear);
          if (level.picture_yardstick) reference = frame;
          if (reference) row["image"] = picture_error(frame, *reference, z_clear);
          if (llvmpipe) row["llvmpipe"] = picture_error(frame, *llvmpipe, z_clear);
        }
        if (level.timing_yardstick && modeled) {
          rtl_time = modeled;
          rtl_counters = row["counters"];
        }
        rows.push_back(row);
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("[%zu/%zu] %s %s %s: wall %.3f s, modeled %s; ETA %.0f s\n", done, total, input.c_str(),
                    level.name.c_str(), variant.label.c_str(), wall,
                    modeled ? (std::to_string(*modeled) + " s").c_str() : "-", elapsed / done * (total - done));
        std::fflush(stdout);
      }
      // Errors against this input x variant's rtl row.
      for (size_t i = first_row; i < rows.size() && rtl_time; ++i) {
        json& row = rows[i];
        if (row.contains("invalid")) continue;
        if (!row["modeled_time_s"].is_null())
          row["time_error"] = (row["modeled_time_s"].get<double>() - *rtl_time) / *rtl_time;
        // Counts of a complete run only: a sampled one counts its sample.
        if (row["level"] != yardstick && row["level"] != exact && row["complete"].get<bool>())
          row["counter_error"] = relative_differences(row["counters"], rtl_counters);
      }
    }
  }

  json level_kinds = json::array();
  for (const AccuracyLevel& level : levels) level_kinds.push_back(level_kind(level));
  const json level_table = level_summary(rows);
  const json counter_table = counter_summary(rows);
  const json agreement = rtl_agreement(rows, yardstick, exact);
  OutputSet files(a.out_dir);
  std::string command = "girtd accuracy";  // what regenerates this run (docs/studies.md quotes it)
  for (const std::string& i : a.inputs) command += " " + i;
  if (!a.levels.empty()) {
    command += " --backends ";
    for (size_t i = 0; i < a.levels.size(); ++i) command += (i ? "," : "") + a.levels[i];
  }
  for (const std::string& v : a.vary) command += " --vary " + v;
  for (const std::string& c : a.config) command += " --config " + c;
  command += " --out " + a.out_dir;
  files.add_text("accuracy.json", json{{"command", command}, {"rows", rows}, {"level_kinds", level_kinds}, {"levels", level_table}, {"counters", counter_table}, {"rtl_agreement", agreement}, {"variants", variant_table},
                                       {"inputs", inputs}, {"config", a.config}}
                                      .dump(2) + "\n");
  files.add_text("accuracy.csv", accuracy_csv(rows));
  const std::string md = accuracy_markdown(rows, level_table, counter_table, agreement) + "\n" +
                         variants_markdown(variant_table);
  files.add_text("accuracy.md", "# girtd accuracy\n\n" + md);
  const std::optional<ChartLibrary> charts = load_chart_library();
  if (!charts) std::fprintf(stderr, "warning: accuracy.html: %s\n", kNoChartLibrary);
  files.add_text("accuracy.html", accuracy_html(command, rows, level_table, charts));
  files.commit();
  std::fputs(md.c_str(), stdout);
  std::printf("wrote %s, accuracy.csv, accuracy.md, accuracy.html\n", files.path("accuracy.json").c_str());
  int failed = 0;
  for (const json& r : rows) failed += r.contains("invalid") && r["invalid"].get<std::string>().rfind("the render failed", 0) == 0;
  for (const json& a : agreement) failed += a["agrees"] == false;
  if (failed) std::printf("%d failure(s): renders that failed, or pictures that differ from rtl's\n", failed);
  return failed ? 1 : 0;
}

}  // namespace girtd
