// girtd::render: read the input, run it on one back end through the frame
// driver, and make the report. What `girtd render` adds (the output folder,
// the page, the summary lines) is the CLI's (cli/render_command.cpp).
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "api/girtd.hpp"
#include "backends/front_end_runner.hpp"
#include "backends/render_session.hpp"
#include "io/output_set.hpp"
#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"
#include "config/config_layers.hpp"
#include "engine/backend_registry.hpp"
#include "io/input_reader.hpp"
#include "io/progress_line.hpp"
#include "io/scene_reader.hpp"
#include "io/sha256.hpp"
#include "layout/rtl_package.hpp"
#include "pipeline/pipeline.hpp"
#include "report/limit_warnings.hpp"
#include "report/report.hpp"
#include "rtl/rtl_build_info.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

// A library caller may name any back end: an unknown one is bad input.
const BackendEntry& known_backend(const std::string& name) {
  if (const BackendEntry* b = find_backend(name)) return *b;
  std::string known;
  for (const std::string& n : backend_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("--backend", 0, "no back end named \"" + name + "\" (known: " + known + ")");
}

DumpRequest parse_dump(const std::string& spec) {
  const size_t eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
    throw InputError("--dump", 0, "expected LEVEL=FILE, got '" + spec + "'");
  const TraceLevel level = parse_level(spec.substr(0, eq), "--dump", 0);
  // A thesis-level trace holds the appendix program's input, which no stage boundary carries.
  if (level == TraceLevel::kThesis)
    throw InputError("--dump", 0, "thesis: not a stage boundary (dump polygon, triangle or dda)");
  return {level, spec.substr(eq + 1)};
}

// The options this back end refuses (its registry entry), before anything is read.
void reject_unbuilt_options(const RenderRequest& a, const BackendEntry& backend) {
  const std::map<std::string, bool> given = {{"--wave", !a.wave.empty()}, {"--sample-timing", bool(a.sample_timing)}};
  for (const BackendRefusal& r : backend.refuses) {
    const auto it = given.find(r.option);
    if (it == given.end()) throw std::logic_error("a refusal of an option render does not have: " + r.option);
    if (it->second) throw InputError(r.option, 0, r.reason);
  }
  // The dump level is checked before the input is read (parse_dump refuses a bad one).
  if (!a.dump.empty() && parse_dump(a.dump).level == TraceLevel::kDda && !backend.has_dda())
    throw InputError("--dump", 0, "dda: the " + backend.name + " back end has no DDA: dump dda from a back end that has one");
  if (a.sample_timing && !(*a.sample_timing > 0 && *a.sample_timing <= 1))
    throw InputError("--sample-timing", 0, "the rate must lie in (0, 1]");
  if (a.repeat < 1) throw InputError("--repeat", 0, "draws an input at least once");
}

ConfigLayers config_layers(const std::vector<ConfigLayer>& layers) {
  ConfigLayers merged = ConfigLayers::builtin();
  for (const ConfigLayer& l : layers) {
    if (!l.file.empty()) merged.merge_file(l.file);
    else merged.merge_json(l.patch, l.origin);
  }
  return merged;
}

Params request_params(const RenderRequest& a) {
  Params params = Params::from_layers(config_layers(a.config));
  if (a.aa) {  // the shorthand for dda.q_override
    params.q_override = *a.aa;
    params.source["dda"]["q_override"] = *a.aa;
  }
  return params;
}

// What a render draws, taken a frame at a time: a trace, or for models and
// scenes polygon-level input (the front end runs in the back end's loop).
FrameSource open_request_input(const RenderRequest& a, const Params& params) {
  std::optional<TraceLevel> level;
  if (!a.level.empty()) level = parse_level(a.level, "--level", 0);
  FrameSource input = a.scene ? open_scene_document(*a.scene, a.input, params, a.camera)
                              : open_input(a.input, level, params, a.camera);
  input.repeat(size_t(a.repeat));  // a static input as N frames: the pipeline overlaps them
  return input;
}

std::string sampling_warning(const std::string& input, const SamplingStats& m, const Params& params) {
  char w[320];
  std::snprintf(w, sizeof w,
                "%s: sampled timing at rate %g: %llu of %llu triangles drawn, the frame is incomplete; the modeled "
                "time is an estimate (+-%.3g s at 99.7 %%)",
                input.c_str(), m.rate, static_cast<unsigned long long>(m.measured + m.warmed),
                static_cast<unsigned long long>(m.measured + m.warmed + m.skipped),
                m.ci_half_ticks * params.base_tick_ns * 1e-9);
  return w;
}

}  // namespace

RenderResult render(const RenderRequest& a) {
  const BackendEntry& entry = known_backend(a.backend);
  reject_unbuilt_options(a, entry);
  const Params params = request_params(a);
  std::optional<WaveOptions> wave;  // checked before the input is read
  if (!a.wave.empty() || !a.wave_window.empty() || !a.wave_scopes.empty())
    wave = parse_wave_options(a.wave, a.wave_window, a.wave_scopes, params.dda_clock_ns, params.base_tick_ns);
  if (wave) check_output_dir(fs::path(wave->path).parent_path().string(), "--wave");
  if (params.q_override && !is_hardware_q(*params.q_override) && entry.has_dda())
    throw InputError(a.aa ? "--aa" : "dda.q_override", 0,
                     "Q must be 0 or a power of two 1/16..8 for the hardware back ends");
  if (entry.has(kRunsRtl) && !holds_rtl_key(rtl_build_key(params)))
    throw InputError("--config", 0,
                     "the rtl back end here holds the RTL elaborated for " + std::string(built_rtl_key()) +
                         "; this configuration needs another (" +
                         rtl_build_differences(nlohmann::json::parse(built_rtl_values()), rtl_build_values(params)) +
                         "): render it with tools/girtd, which builds that RTL variant");
  const uint64_t passes_before = front_end_passes();
  ProgressLine::get().start(a.progress);
  FrameSource input = open_request_input(a, params);
  const std::vector<std::string> input_warnings = input.warnings();
  auto warn = [&](const std::string& w) {
    if (!a.print_warnings) return;
    ProgressLine::get().end();
    std::fprintf(stderr, "warning: %s\n", one_line(w).c_str());
  };
  for (const std::string& w : input_warnings) warn(w);

  RenderOptions opt;
  opt.keep_all_frames = a.keep_all_frames;
  if (!a.dump.empty()) opt.dump = parse_dump(a.dump);
  opt.on_frame = a.on_frame;
  opt.progress = a.progress;
  opt.wave = wave;
  opt.prune = plan_pruning(input.level(), a.prune);
  opt.sample_timing = a.sample_timing;
  RenderOutput out = entry.timed() ? run_pipeline(entry, input, params, opt) : render_frames(entry, input, params, opt);
  if (out.problem) {  // found at the end of the run: not thrown (see RenderResult::problem)
    RenderResult failed;
    failed.problem = out.problem;
    return failed;
  }

  ReportContext ctx;
  ctx.backend = entry.name;
  ctx.capabilities = entry.capabilities;
  ctx.input = a.input;
  ctx.level = level_name(input.level());
  ctx.image_sha256 = sha256_hex(out.shown.rgb);
  for (const std::string& w : input_warnings) ctx.warnings.push_back(one_line(w));
  std::vector<std::optional<std::string>> run_warnings = {
      limit_warning(a.input, out.stats, params), seam_warning(a.input, out.stats), culling_warning(a.input, out.stats)};
  // Sampled timing draws part of the frame: never a silently incomplete picture.
  if (out.stats.sampling) run_warnings.push_back(sampling_warning(a.input, *out.stats.sampling, params));
  for (const auto& w : run_warnings)
    if (w) {  // a hardware limit hit or a seam: counted and warned
      warn(*w);
      ctx.warnings.push_back(one_line(*w));
    }
  if (entry.has(kRunsRtl)) ctx.rtl_build = built_rtl_key();
  ctx.front_end_passes = front_end_passes() - passes_before;
  ctx.left_out = left_out(out.stats);

  RenderResult r;
  r.report = make_report(ctx, out.stats, params);
  r.frame = std::move(out.shown);
  r.z = std::move(out.z);
  r.per_frame = std::move(out.per_frame);
  r.wave_files = std::move(out.wave_files);
  r.stats = std::move(out.stats);
  return r;
}

bool runs_once_per_process(const std::string& backend) { return known_backend(backend).timed(); }

nlohmann::json backend_list() {
  nlohmann::json list = nlohmann::json::array();
  for (const BackendEntry& e : backend_registry()) {
    nlohmann::json refuses = nlohmann::json::object();
    for (const BackendRefusal& r : e.refuses) refuses[r.option] = r.reason;
    list.push_back({{"name", e.name},
                    {"summary", e.summary},
                    {"timed", e.timed()},
                    {"has_dda", e.has_dda()},
                    {"records_waveforms", e.refusal("--wave") == nullptr},
                    {"runs_rtl", e.has(kRunsRtl)},
                    {"once_per_process", e.timed()},
                    {"not_modeled", not_modeled(e)},
                    {"refuses", refuses}});
  }
  return list;
}

nlohmann::json merged_config(const std::vector<ConfigLayer>& layers) {
  return Params::from_layers(config_layers(layers)).source;
}

std::string needed_rtl_key(const std::vector<ConfigLayer>& layers) {
  return rtl_build_key(Params::from_layers(config_layers(layers)));
}

bool holds_rtl_key(const std::string& key) { return key == built_rtl_key(); }

}  // namespace girtd
