// girtd: the command line (docs/interface.md). The simulator's own
// subcommands (render, regress: sim/cli) and the campaigns on top of it
// (bench, claims, stress, accuracy, sweep: studies/), and `--plan`, which
// tells the driver what a command needs before it runs.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>

#include "accuracy/accuracy_command.hpp"
#include "accuracy/accuracy_levels.hpp"
#include "bench/bench_command.hpp"
#include "bench/golden_speed_bench.hpp"
#include "bench/animation_bench.hpp"
#include "bench/scale_bench.hpp"
#include "claims/claims_command.hpp"
#include "cli/commands.hpp"
#include "common/input_error.hpp"
#include "engine/backend_registry.hpp"
#include "io/progress_line.hpp"
#include "rtl/rtl_variants.hpp"
#include "stress/stress_cases.hpp"
#include "stress/stress_command.hpp"
#include "sweep/sweep_command.hpp"

namespace {
constexpr const char* kConfigHelp =
    "JSON file merged over config/girtd.json; repeat to merge several in order (the later wins)";
}

int main(int argc, char** argv) {
  using namespace girtd;
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);  // before SystemC starts
  CLI::App app{"GIRTD-sim: cycle-approximate simulator of the GIRTD 3D image generator (1988)"};
  app.require_subcommand(1);
  bool plan = false;
  app.add_flag("--plan", plan,
               "print what must exist before the command runs (RTL variants, synthesised sizes, a workload, a Slurm "
               "array, plots to draw after), one tab-separated line each, and exit: the driver tools/girtd makes them")
      ->group("");

  RenderArgs ra;
  CLI::App* render = app.add_subcommand("render", "render a model (any format assimp reads: OBJ, glTF, Collada, ...), a scene (JSON) or a trace");
  render->add_option("input", ra.input, "model, scene or trace file (traces/FORMAT.md)")->required();
  std::string backend_choices;
  for (const std::string& n : backend_names()) backend_choices += (backend_choices.empty() ? "" : " | ") + n;
  render->add_option("--backend", ra.backend, backend_choices)
      ->check(CLI::IsMember(backend_names()))
      ->capture_default_str();
  render->add_option("--out", ra.out_dir, "output directory (default out/<input name>/)");
  render->add_option("--level", ra.level, "level of a headerless trace: polygon | triangle | dda | thesis")
      ->check(CLI::IsMember({"polygon", "triangle", "dda", "thesis"}));
  render->add_option("--camera", ra.camera, "a model file's camera by name (default: the file's first, else auto-framed)");
  render->add_option("--frames", ra.frames, "last | all (one PNG per frame)")
      ->check(CLI::IsMember({"last", "all"}))
      ->capture_default_str();
  CLI::Option* wave = render->add_option("--wave", ra.wave, "waveform file (.fst or .vcd)");
  render->add_option("--wave-window", ra.wave_window, "T0:T1 window of the waveform")->needs(wave);
  render->add_option("--wave-scope", ra.wave_scopes, "module path to record (repeatable)")->needs(wave);
  render->add_option("--aa", ra.aa, "antialiasing width Q for every frame, over the input's (shorthand for dda.q_override)")
      ->check(CLI::NonNegativeNumber);
  render->add_option("--dump", ra.dump, "LEVEL=FILE: record the stream at a stage boundary");
  render->add_option("--config", ra.config, kConfigHelp)->allow_extra_args(false);
  render->add_flag("--z-png", ra.z_png, "also write z.png (16-bit depth)");
  render->add_option("--compare", ra.compare,
                     "reference: also render on the reference back end and put the error heat map and its histogram "
                     "into report.html")
      ->check(CLI::IsMember({backend_with(kExactPicture).name}));
  render->add_flag("--quiet", ra.quiet, "print nothing on success");
  render->add_flag("--no-prune", ra.no_prune,
                   "compute everything, even what no output depends on (the same outputs; report.json's left_out "
                   "lists what a pruned run skipped)");
  render->add_option("--repeat", ra.repeat,
                     "draw a one-frame input N times as N frames; the timed back ends then judge the sustained rate "
                     "(frames 2..N, report.json's sustained_mpixels_per_s)")
      ->check(CLI::Range(1, 100000));
  render->add_option("--sample-timing", ra.sample_timing,
                     "approx: of every round(1/RATE) triangles, time one, simulate the one before it as warm-up "
                     "and skip the rest (a timing estimate with a confidence interval, report.json's `sampling`; "
                     "the frame is incomplete). The accuracy command's approx_sampled_<RATE> level");

  ConfigFiles claims_config;
  CLI::App* claims = app.add_subcommand("claims", "the thesis' claims (docs/design.md §9) against measurements");
  claims->add_option("--config", claims_config, kConfigHelp)->allow_extra_args(false);
  bool claims_campaign = false;
  claims->add_flag("--campaign", claims_campaign,
                   "only chapter 5's rows read from the study campaign's stored results (fast; docs/studies.md's table)");

  BenchArgs ba;
  CLI::App* bench = app.add_subcommand("bench", "speed and error tables of the back ends");
  bench->add_option("--config", ba.config, kConfigHelp)->allow_extra_args(false);
  bench->add_option("--out", ba.out, "output directory")->capture_default_str();
  CLI::Option* pipeline_only = bench->add_flag("--pipeline", ba.pipeline_only,
                  "only the SystemC pipeline's table (approx against rtl, every back end against the stored "
                  "expectations); exit 1 on a disagreement");
  CLI::Option* inputs =
      bench->add_option("inputs", ba.inputs, "with --pipeline: these inputs only (default: traces/workloads.txt)")
          ->check(CLI::ExistingFile)
          ->needs(pipeline_only);
  CLI::Option* leave_out = bench->add_flag("--leave-out", ba.leave_out_only,
                  "only the culling (modeled) and pruning (wall time, median of 5) tables, and what pruning could save at most")
      ->excludes(pipeline_only);
  CLI::Option* speed = bench->add_flag("--speed", ba.speed_only,
                  "only the simulator's speed tables (rtl DDA clocks per wall second against the DDA alone; golden against single-threaded llvmpipe on 20,000 random 200-pixel triangles; what report.html's series cost, the median ratio over pairs of renders)")
      ->excludes(pipeline_only)
      ->excludes(leave_out);
  CLI::Option* scale = bench->add_flag("--scale", ba.scale_only,
                  "only the simulator's cost against the input's size: generated meshes (default 10^4, 10^5 and 10^6 "
                  "triangles) rendered end to end on golden and approx beside assimp's import alone (elapsed time, peak "
                  "memory, growth exponents), and a turning sphere's long animation against a short one (peak memory)")
      ->excludes(pipeline_only)
      ->excludes(leave_out)
      ->excludes(speed);
  ba.scale_sizes = kDefaultScaleSizes;
  bench->add_option("--sizes", ba.scale_sizes, "with --scale: the meshes' triangle counts")
      ->check(CLI::Range(100L, 20000000L))
      ->needs(scale);
  ba.animation_frames = {kShortAnimation, kLongAnimation};
  bench->add_option("--frames", ba.animation_frames,
                    "with --scale: the animation's short and long frame counts (rtl draws at most " +
                        std::to_string(kLongAnimationRtl) + " frames)")
      ->expected(2)
      ->check(CLI::Range(1L, 100000L))
      ->needs(scale);
  bench->add_option("--runs", ba.scale_runs, "with --scale: runs per size (medians)")
      ->check(CLI::Range(1, 50))
      ->capture_default_str()
      ->needs(scale);
  bench->add_flag("--bless", ba.bless, "with --pipeline: rewrite testbench/golden/expectations.json from this run")
      ->needs(pipeline_only)
      ->excludes(inputs);

  bench->add_flag("--options", ba.option_matrix,
                  "with --pipeline: the table under each memory-side option alone and all together (write-behind, "
                  "prefetch, dirty bits, stolen VRAM cycles; default inputs: traces/accuracy_inputs.txt)")
      ->needs(pipeline_only)
      ->excludes("--bless");

  RegressArgs rg;
  CLI::App* regress = app.add_subcommand("regress", "RTL against the golden model, trace by trace");
  regress->add_option("traces", rg.traces, "traces (default: the triangle- and DDA-level traces of traces/workloads.txt)");
  regress->add_option("--random", rg.random, "also N random triangles")->check(CLI::NonNegativeNumber);
  regress->add_option("--seed", rg.seed, "seed of the random triangles")->capture_default_str();
  regress->add_option("--stall", rg.stall, "back-pressure probability on every other triangle")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  regress->add_flag("--both-compare-modes", rg.both_compare_modes, "run same-cycle and pipelined X/Y compare");
  regress->add_flag("--dda-only", rg.dda_only, "compare the DDA alone, not the whole RTL back end");
  regress->add_option("--config", rg.config, kConfigHelp)->allow_extra_args(false);

  StressArgs st;
  CLI::App* stress = app.add_subcommand("stress", "generated extreme cases on reference, golden and rtl");
  stress->add_option("--family", st.families, "a family (repeatable; default: all)")
      ->check(CLI::IsMember(stress_families()));
  stress->add_option("--config", st.config, kConfigHelp)->allow_extra_args(false);
  stress->add_option("--out", st.out_dir, "output directory")->capture_default_str();
  stress->add_flag("--fast", st.fast, "a few cases of each family (the CTest subset)");
  stress->add_option("--timeout", st.timeout_s, "seconds a render may take before it counts as a hang")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();

  AccuracyArgs ac;
  CLI::App* accuracy = app.add_subcommand("accuracy", "error against run time: timing estimators against rtl, "
                                                      "pictures against the reference and llvmpipe");
  accuracy->add_option("inputs", ac.inputs, "inputs (default: traces/accuracy_inputs.txt)")->check(CLI::ExistingFile);
  std::string default_levels;
  for (const std::string& l : default_accuracy_levels(backend_registry()))
    default_levels += (default_levels.empty() ? "" : ",") + l;
  accuracy->add_option("--backends", ac.levels,
                       "levels, comma-separated: " + accuracy_level_names(backend_registry()) + " (default " +
                           default_levels + "; the reference always runs)")
      ->delimiter(',');
  accuracy->add_option("--vary", ac.vary, "KEY=V1,V2,...: a configuration key's values (repeatable: every combination)");
  accuracy->add_option("--config", ac.config, kConfigHelp)->allow_extra_args(false);
  accuracy->add_option("--out", ac.out_dir, "output directory")->capture_default_str();

  SweepArgs sw;
  CLI::App* sweep = app.add_subcommand("sweep", "a design-space sweep: every combination of the spec's axes on its inputs");
  sweep->add_option("spec", sw.spec, "SPEC.json (docs/interface.md; traces/sweeps/)")->required()->check(CLI::ExistingFile);
  sweep->add_option("--jobs", sw.jobs, "renders at once (default: every core); with --slurm, array tasks (default 64)")
      ->check(CLI::PositiveNumber);
  sweep->add_option("--out", sw.out_dir, "output directory (default out/sweep/<spec name>; a rerun resumes there)");
  sweep->add_flag("--slurm", sw.slurm,
                  "run the rows as a Slurm job array, then gather (submitted by the driver: tools/girtd sweep ... --slurm)");
  sweep->add_option("--slice", sw.slice, "I/S: run rows I, I + S, ... only, and no tables (what each Slurm task runs)")
      ->group("");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "girtd: %s\n", e.what());
    return 2;
  }

  try {
    // A configuration the built RTL is not elaborated for runs in an RTL
    // variant (render on rtl; regress, bench, claims and stress drive the RTL
    // too). A render whose input is missing fails at once, before any variant;
    // its plan does not wait for the input (the driver remembers an empty plan).
    const bool renders_on_rtl = *render && backend_named(ra.backend).has(kRunsRtl);
    const bool campaign_drives_rtl = *regress || *bench || *claims || *stress;
    const ConfigFiles& config = *render ? ra.config
                                : *regress ? rg.config
                                : *bench   ? ba.config
                                : *stress  ? st.config
                                           : claims_config;
    if (plan) {
      std::vector<std::string> lines;
      if (renders_on_rtl || campaign_drives_rtl) {
        const Params p = load_params(config);
        if (const auto v = needed_rtl_variant(p)) lines.push_back(rtl_variant_plan_line(*v, p));
      }
      if (*bench && ba.speed_only) lines.push_back(golden_speed_bench_plan_line(ba.out));
      if (*bench && ba.scale_only) {
        lines = scale_bench_plan_lines(ba.out, ba.scale_sizes);
        for (const std::string& l : animation_bench_plan_lines(ba.out)) lines.push_back(l);
      }
      if (*accuracy) lines = plan_accuracy(ac);
      if (*sweep) lines = plan_sweep(sw);
      for (const std::string& line : lines) std::printf("%s\n", line.c_str());
      return 0;
    }
    if ((renders_on_rtl && std::filesystem::exists(ra.input)) || campaign_drives_rtl)
      run_in_rtl_variant_if_needed(load_params(config), argv);
    if (*render) return run_render(ra);
    if (*claims) return run_claims(claims_config, claims_campaign);
    if (*bench) return run_bench(ba);
    if (*regress) return run_regress(rg);
    if (*stress) return run_stress(st);
    if (*accuracy) return run_accuracy(ac);
    if (*sweep) return run_sweep(sw);
  } catch (const InputError& e) {
    ProgressLine::get().end();
    std::fprintf(stderr, "%s\n", e.formatted().c_str());
    return 2;
  } catch (const MissingPrerequisite& e) {
    ProgressLine::get().end();
    std::fprintf(stderr, "girtd: %s\n", e.what());
    return kExitMissingPrerequisite;
  } catch (const std::exception& e) {
    ProgressLine::get().end();
    std::fprintf(stderr, "girtd: internal error: %s\n", e.what());
    return 3;
  }
  return 2;
}
