// girtd claims: docs/design.md §9, each thesis claim next to what this simulator
// measures. A row with no measurement yet says so. The front end's rows run
// the timed pipeline in a child process (SystemC elaborates once per process).
#include <unistd.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "claims/campaign_claims.hpp"
#include "claims/dda_efficiency.hpp"
#include "claims/ep_error.hpp"
#include "claims/ep_precision.hpp"
#include "claims/numeric_limits.hpp"
#include "girtd/design_constants.hpp"
#include "io/subprocess.hpp"
#include "io/text_format.hpp"
#include "claims/thesis_losses.hpp"
#include "claims/claims_command.hpp"
#include "cli/config_loader.hpp"
#include "layout/rtl_layout.hpp"
#include "common/input_error.hpp"
#include "rtl/memory_measurements.hpp"
#include "frontend/stage_costs.hpp"

namespace girtd {
namespace fs = std::filesystem;
namespace {

// "confirmed" within 5 % of the thesis value, else "refuted".
std::string verdict(double measured, double thesis) {
  return std::fabs(measured - thesis) <= 0.05 * std::fabs(thesis) ? "confirmed" : "refuted";
}

void dda_rows(const Params& p, std::vector<ClaimRow>& rows) {
  const double mhz = 1e3 / p.dda_clock_ns;  // Mclocks/s
  for (double q : {0.0, 1.0}) {
    for (bool ttl : {false, true}) {
      const EfficiencySample up = measure_equilateral(p, Orientation::kApexUp, q, ttl);
      const EfficiencySample down = measure_equilateral(p, Orientation::kApexDown, q, ttl);
      const EfficiencySample rnd = measure_equilateral(p, Orientation::kRandom, q, ttl);
      const double mean_eff = (up.mean_efficiency + down.mean_efficiency) / 2;
      const std::string cfg = format_numbers("Q = %g, ", q) + (ttl ? "+2 clocks/line (TTL)" : "same-cycle compare (ECL)");
      rows.push_back({"DDA efficiency, 200-px equilateral, " + cfg, "70 % (86 wasted states)",
                      format_numbers("%.1f %% (up %.1f %%, %.0f..%.0f wasted; ", 100 * mean_eff, 100 * up.mean_efficiency,
                          up.min_wasted, up.max_wasted) +
                          format_numbers("down %.1f %%, %.0f..%.0f wasted; random rot. %.1f %%)", 100 * down.mean_efficiency,
                              down.min_wasted, down.max_wasted, 100 * rnd.mean_efficiency),
                      verdict(mean_eff, 0.70)});
      rows.push_back({"wasted states vs the per-edge formula, " + cfg, "apex up 95.9, apex down 77.3 (formula)",
                      format_numbers("up %.1f (formula %.1f), down %.1f (formula %.1f)", up.mean_wasted, up.mean_thesis_wasted,
                          down.mean_wasted, down.mean_thesis_wasted),
                      verdict(up.mean_wasted + down.mean_wasted, up.mean_thesis_wasted + down.mean_thesis_wasted)});
      rows.push_back({"DDA pixel rate at " + format_numbers("%.0f ns, ", p.dda_clock_ns) + cfg, "20 Mpixel/s (200 px)",
                      format_numbers("%.1f Mpixel/s (emitted %.0f px)", mean_eff * mhz, (up.mean_emitted + down.mean_emitted) / 2),
                      verdict(mean_eff * mhz, p.target_mpixels_per_s)});
    }
  }
  // The thesis' figures follow from its timings (config/girtd.json's defaults): one pixel per
  // DDA clock, which it states rounded down (28 Mpixel/s at 35 ns).
  const double thesis_peak = 1e3 / Params::defaults().dda_clock_ns;
  rows.push_back({"DDA peak rate at " + format_numbers("%.0f ns", p.dda_clock_ns),
                  format_numbers("%.0f Mpixel/s", std::floor(thesis_peak)),
                  format_numbers("%.1f Mpixel/s (one pixel per clock)", mhz), verdict(mhz, thesis_peak)});
}

void error_rows(const Params& p, std::vector<ClaimRow>& rows) {
  const EpErrorSample e = measure_ep_error(p, 300, kLargestTrianglePx, kAcrossSteps, 4242);
  const double colour_bound = 1.0 + std::ldexp(1.0, -p.ep_color.frac_bits - 1);
  const double d_bound = 0.125 + std::ldexp(1.0, -p.ep_d.frac_bits - 1);
  rows.push_back({format_numbers("error after <= %.0f steps, colour", kAcrossSteps), "<= 1 colour LSB",
                  format_numbers("max %.3f LSB over %.0f pixels (<= %.0f steps)", e.max_color_lsb, double(e.pixels), e.max_steps),
                  e.max_color_lsb <= colour_bound ? "confirmed" : "refuted"});
  rows.push_back({format_numbers("error after <= %.0f steps, edge distance", kAcrossSteps), "<= 0.125 px",
                  format_numbers("max %.4f px", e.max_d_px), e.max_d_px <= d_bound ? "confirmed" : "refuted"});
}

// A row per EP: is the hardware chapter's fraction width the fewest that
// keeps the thesis' budget over a walk across the screen (claims/ep_precision.hpp)?
void precision_rows(const Params& p, std::vector<ClaimRow>& rows) {
  for (EpKind ep : kEpKinds) {
    const EpPrecision r = ep_precision(p, ep);
    const std::string key = std::string("ep.") + ep_key(ep) + ".frac_bits";
    const std::string unit = ep_unit(ep);
    std::string verdict = "confirmed";
    if (r.fewest_across < 0) verdict = format_numbers("refuted (needs more than %.0f bits)", r.configured + 8);
    else if (r.fewest_across < r.configured) verdict = format_numbers("refuted (%.0f bits suffice)", r.fewest_across);
    else if (r.fewest_across > r.configured) verdict = format_numbers("refuted (needs %.0f bits)", r.fewest_across);
    rows.push_back({"fraction bits of EP " + std::string(ep_key(ep)) + " (" + key + format_numbers(" = %.0f)", r.configured),
                    format_numbers(ep == EpKind::kD ? "<= %.3f px over %.0f steps" : "<= %.0f LSB over %.0f steps", ep_budget(ep), kAcrossSteps) +
                        (ep == EpKind::kZ ? format_numbers(" (no budget stated for Z: 1 LSB of its %.0f-bit output assumed)", kZOutBits)
                                           : std::string()) +
                        " (+ half a fraction LSB: the start value's rounding)",
                    (r.fewest_corner < 0
                         ? format_numbers("fewest keeping it: %.0f bits over %.0f steps, none up to %.0f over %.0f; ",
                                          r.fewest_across, kAcrossSteps, r.configured + 8, kCornerSteps)
                         : format_numbers("fewest keeping it: %.0f bits over %.0f steps, %.0f over %.0f; ", r.fewest_across,
                                          kAcrossSteps, r.fewest_corner, kCornerSteps)) +
                        format_numbers("with %.0f: ", r.configured) + format_numbers("%.3f ", r.error_across) + unit +
                        format_numbers(" (%.0f), %.3f ", kAcrossSteps, r.error_corner) + unit +
                        format_numbers(" (%.0f); 2,000 random triangles", kCornerSteps),
                    verdict});
  }
}

// How often the demo and the sample models hit a limit or show seams: a
// golden render of each in a child process, as a user would run it.
void limits_in_samples(const ConfigFiles& config, std::vector<ClaimRow>& rows) {
  const std::string dir = (std::filesystem::temp_directory_path() / ("girtd_claims_" + std::to_string(getpid()))).string();
  std::string measured;
  int hit = 0, inputs = 0;
  for (const char* in : {"traces/scenes/demo.json", "traces/models/torus.obj", "traces/models/sphere.ply",
                         "traces/models/cube.off", "traces/models/star.obj", "traces/scenes/near_clip.json"}) {
    if (!std::filesystem::exists(in)) continue;
    std::vector<std::string> args = {self_executable(), "render", in, "--backend", "golden", "--out", dir, "--quiet"};
    for (const std::string& a : config_args(config)) args.push_back(a);
    if (run_process(args, true) != 0) continue;
    std::ifstream f(dir + "/report.json");
    const nlohmann::json r = nlohmann::json::parse(f);
    const uint64_t affected = r.at("numerics").value("triangles_affected", uint64_t{0});
    ++inputs;
    hit += affected > 0;
    measured += std::string(measured.empty() ? "" : "; ") + std::filesystem::path(in).filename().string() + ": " +
                format_numbers("%.0f of %.0f triangles, ", double(affected), r.at("triangles_drawn").get<double>()) +
                format_numbers("%.0f seam pixels", r.at("pixels_reblended").get<double>());
  }
  std::filesystem::remove_all(dir);
  rows.push_back({"limits hit by the demo and sample models (golden)", "(not discussed)",
                  format_numbers("%.0f of %.0f inputs hit a limit: ", hit, inputs) + measured, "measured"});
}

// Issue 17: where the formats stop drawing right, and how often real inputs get there.
void numerics_rows(const Params& p, const ConfigFiles& config, std::vector<ClaimRow>& rows) {
  std::string growth;
  for (int steps : {kAcrossSteps / 4, kAcrossSteps, kCornerSteps}) {
    const EpErrorSample e = measure_ep_error(p, 100, kLargestTrianglePx, steps, 4242);
    growth += std::string(growth.empty() ? "" : "; ") + format_numbers("<= %.0f steps: ", steps) +
              format_numbers("colour %.3f, T %.3f, ", e.max_color_lsb, e.max_t_lsb) +
              format_numbers("Z %.3f LSB, D %.4f px", e.max_z_lsb, e.max_d_px);
  }
  rows.push_back({format_numbers("EP error growth with the steps walked (100 random triangles up to %.0f px)", kLargestTrianglePx),
                  "grows by half an LSB of the derivative per step", growth, "measured"});
  std::string collapse;
  for (double area : {1e3, 1e2, 10.0, 1.0, 1e-6, 1e-12}) {
    const CollapseSample c = measure_collapse(p, area);
    collapse += std::string(collapse.empty() ? "" : "; ") + format_numbers("area %g: ", area) +
                format_numbers("%.0f dropped, ", double(c.dropped)) + format_numbers("%.0f clamped, ", double(c.clamped_values)) +
                format_numbers("%.0f px, ", double(c.pixels)) + format_numbers("worst %.0f LSB", double(c.max_colour_error));
  }
  rows.push_back({"the preparer as a triangle's area goes to 0 (20 slivers, red 0..255 across the height)",
                  "(not discussed)", collapse, "measured"});
  Params far = p;
  far.far_edges_constant = true;
  const double safe = largest_safe_overhang(p), safe_far = largest_safe_overhang(far);
  rows.push_back({"D EPs' safe range: largest overhang of a screen-filling triangle drawn right",
                  format_numbers("%.0f integer bits hold the screen", p.ep_d.int_bits),
                  format_numbers("%.0f px beyond the screen; ", safe) +
                      format_numbers("with preparer.far_edges constant: %.0f px (the corners at the input limit, 1e6)", safe_far),
                  safe >= 0 ? "confirmed" : "refuted"});
  limits_in_samples(config, rows);
}

void thesis_rows(const Params& p, std::vector<ClaimRow>& rows) {
  for (ThesisInside inside : {ThesisInside::kProgram, ThesisInside::kSharp}) {
    const ThesisLossSample s = measure_thesis_losses(p, inside, 4000, 1988);
    const bool program = inside == ThesisInside::kProgram;
    rows.push_back({std::string("DDApix as written (appendix), ") + (program ? "its own D >= -1" : "sharp D >= 0"),
                    "fig. 4.2 visits every inside pixel",
                    format_numbers("loses pixels on %.1f %% of %.0f random triangles (%.2f %% of inside pixels); ",
                        100.0 * s.triangles_losing / std::max(1, s.triangles), s.triangles,
                        100.0 * double(s.lost_pixels) / double(std::max<uint64_t>(1, s.inside_pixels))) +
                        format_numbers("%.0f emits past Xmin/Xmax", double(s.outside_limit_emits)),
                    s.triangles_losing == 0 ? "confirmed" : "refuted"});
  }
  const ThesisEfficiency up = measure_thesis_equilateral(p, true), down = measure_thesis_equilateral(p, false);
  rows.push_back({"DDApix wasted states, 200-px equilateral on the 128 x 96 screen",
                  "apex up 95.9, apex down 77.3 (formula)",
                  format_numbers("up %.1f (formula %.1f), down %.1f (formula %.1f); ", up.mean_wasted, up.mean_formula,
                      down.mean_wasted, down.mean_formula) +
                      format_numbers("efficiency %.1f %% / %.1f %%", 100 * up.mean_efficiency, 100 * down.mean_efficiency),
                  verdict(up.mean_wasted + down.mean_wasted, up.mean_formula + down.mean_formula)});
}

// Within one base tick of a thesis time: the bar for the directed streams.
std::string within_tick(double measured_ns, double thesis_ns, double tick_ns) {
  return std::fabs(measured_ns - thesis_ns) <= tick_ns ? "confirmed" : "refuted";
}

void memory_rows(const Params& p, std::vector<ClaimRow>& rows) {
  const double vram = 2 * p.vram_cycle_ns;  // a page swap: write back, then fetch
  const StreamTiming row = time_stream(p, PixelStream::kRow), col = time_stream(p, PixelStream::kColumn);
  // A row stream stays in a page for its width, a column stream for its
  // height (16 and 1 with the thesis' 16 x 1 page).
  const PageGeometry page = rtl_layout(p).page;
  const double f16 = p.had_access_ns + vram / page.width_px, f1 = p.had_access_ns + vram / page.height_px;
  rows.push_back({"cache time per pixel (RTL, directed streams)", "52.5 ns at nac = 16, 465 ns at nac = 1",
                  format_numbers("nac = %.0f: %.1f ns (formula %.1f); ", page.width_px, row.ns_per_pixel, f16) +
                      format_numbers("nac = %.0f: %.1f ns (formula %.1f)", page.height_px, col.ns_per_pixel, f1),
                  within_tick(row.ns_per_pixel, f16, p.base_tick_ns) == "confirmed" &&
                          within_tick(col.ns_per_pixel, f1, p.base_tick_ns) == "confirmed"
                      ? "confirmed"
                      : "refuted"});
  Params no_cache = p;  // a cache reduced to a one-pixel buffer: one base tick per access
  no_cache.had_access_ns = p.base_tick_ns;
  const StreamTiming bare = time_stream(no_cache, PixelStream::kColumn);
  const double thesis_no_cache = 1e3 / (2 * Params::defaults().vram_cycle_ns);  // a page read and write per pixel
  rows.push_back({"no-cache rate (every pixel a page read and write)", format_numbers("%.2f Mpixel/s", thesis_no_cache),
                  format_numbers("%.2f Mpixel/s (%.1f ns per pixel)", 1e3 / bare.ns_per_pixel, bare.ns_per_pixel),
                  verdict(1e3 / bare.ns_per_pixel, thesis_no_cache)});
  Params wb = p;
  wb.had_write_behind = true;
  const StreamTiming wb_row = time_stream(wb, PixelStream::kRow);
  rows.push_back({"write-behind register (5.2.2), nac = 16", "halves VRAM time: 25 + 220/16 = 38.75 ns",
                  format_numbers("%.1f ns per pixel (without: %.1f)", wb_row.ns_per_pixel, row.ns_per_pixel),
                  within_tick(wb_row.ns_per_pixel, p.had_access_ns + p.vram_cycle_ns / page.width_px, p.base_tick_ns)});
  Params pf = wb;
  pf.had_prefetch = true;
  const StreamTiming pf_row = time_stream(pf, PixelStream::kRow);
  rows.push_back({"prefetch + write-behind (5.2.2), nac = 16", "~100 % cache hits: ~25 ns per pixel (40 Mpixel/s)",
                  format_numbers("%.1f ns per pixel; the DDA feeds one pixel per %.0f ns at best, and the look-ahead is only as "
                      "deep as the FIFO holds",
                      pf_row.ns_per_pixel, p.dda_clock_ns),
                  within_tick(pf_row.ns_per_pixel, p.had_access_ns, p.base_tick_ns)});

  std::string rates, rates_wb, rates_pf;
  double worst = 1e9;
  for (const char* t : {"traces/equilateral_200.trace", "traces/demo.trace", "traces/z_overlap.trace"}) {
    const TraceTiming a = time_trace(p, t), b = time_trace(wb, t), c = time_trace(pf, t);
    rates += format_numbers("%.1f", a.mpixels_per_s()) + " (" + std::string(t).substr(7) + format_numbers(", nac %.1f); ", a.nac);
    rates_wb += format_numbers("%.1f; ", b.mpixels_per_s());
    rates_pf += format_numbers("%.1f; ", c.mpixels_per_s());
    worst = std::min(worst, a.mpixels_per_s());
  }
  rows.push_back({"end-to-end rate, memory side as written (RTL back end)",
                  "implied >= 20; best case 19, estimate ~10.7 Mpixel/s",
                  "Mpixel/s " + rates + "with write-behind " + rates_wb + "with write-behind and prefetch " + rates_pf,
                  worst >= p.target_mpixels_per_s * 0.95 ? "confirmed" : "refuted"});

  std::string waits;
  bool waits_at_16 = false, measured_16 = false;
  for (int depth : {4, 8, 16, 32}) {
    if (depth > p.fifo_max_depth) continue;  // the RTL FIFO is built no deeper
    Params f = p;
    f.fifo_dda_had_depth = depth;
    const TraceTiming t = time_trace(f, "traces/demo.trace");
    waits += format_numbers("depth %.0f: %.1f %% of DDA clocks; ", depth, 100 * t.dda_wait_fraction);
    if (depth == 16) {
      measured_16 = true;
      waits_at_16 = t.dda_wait_fraction > 0;
    }
  }
  rows.push_back({"FIFO depth 16 suffices (demo trace)", "waits never exceed 16 DDA cycles",
                  "DDA waiting on a full FIFO: " + waits,
                  !measured_16 ? "not yet measured" : waits_at_16 ? "refuted" : "confirmed"});
  rows.push_back({"frame clear", "~108 us serial, 14 ms cache, 230 ms naive",
                  format_numbers("serial port: %.1f us (cache and naive clears not modeled)", frame_clear_us(p)),
                  verdict(frame_clear_us(p), 108)});
}

// The front end's arithmetic, from the timed pipeline on the demo scene (a
// child process: SystemC elaborates once per process).
void preparer_rows(const Params& p, std::vector<ClaimRow>& rows) {
  const double target = p.target_preparer_triangles_per_s;
  const double prep_flops = preparer_ops(p).flops();
  rows.push_back({"preparer load", "40,000 triangles/s: 4.96 Mflop/s (124 flop; 172 from the parts, less 57 for the clip)",
                  format_numbers("%.0f flop per triangle (the thesis' parts): %.2f Mflop/s at %.0f triangles/s; ", prep_flops,
                      prep_flops * target / 1e6, target) +
                      format_numbers("at %.0f Mflop/s it can deliver %.0f triangles/s",
                          p.stage_rate_flops_per_s.at("preparer") / 1e6,
                          p.stage_rate_flops_per_s.at("preparer") / prep_flops),
                  prep_flops * target <= p.stage_flops_per_s ? "confirmed" : "refuted"});

  const std::string scene = "traces/scenes/demo.json";
  if (!fs::exists(scene)) throw InputError(scene, 0, "run claims from the repository root");
  std::string tmpl = (fs::temp_directory_path() / "girtd_claims_XXXXXX").string();
  char* dir = tmpl.data();
  if (!mkdtemp(dir)) throw std::runtime_error("cannot make a temporary directory");
  const int rc = run_process({self_executable(), "render", scene, "--backend", "approx", "--out",
                              std::string(dir) + "/out", "--quiet"},
                             false);
  nlohmann::json r;
  if (rc == 0) r = nlohmann::json::parse(std::ifstream(std::string(dir) + "/out/report.json"));
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (rc != 0) throw std::runtime_error("the demo scene did not render on approx");
  const double triangles = r.at("frontend").at("triangles_out");
  std::string need;
  double worst = 0;
  std::string worst_stage;
  for (const nlohmann::json& name : r.at("stage_order")) {
    const nlohmann::json& st = r.at("stages").at(name.get<std::string>());
    if (!st.contains("flops") || st.at("flops").is_null()) continue;
    const double mflops = st.at("flops").get<double>() / triangles * target / 1e6;
    need += name.get<std::string>() + format_numbers(" %.1f, ", mflops);
    if (mflops > worst) {
      worst = mflops;
      worst_stage = name.get<std::string>();
    }
  }
  rows.push_back({"every stage within 10 Mflop/s at 40,000 triangles/s", "at most 10 Mflop/s per stage",
                  "Mflop/s each stage needs on " + scene + " (" + format_numbers("%.0f", triangles) + " triangles, one light): " +
                      need + "most: " + worst_stage,
                  worst <= p.stage_flops_per_s / 1e6 ? "confirmed" : "refuted"});
}

void print_claims(const std::vector<ClaimRow>& rows) {
  std::printf("| claim | thesis | measured | verdict |\n|---|---|---|---|\n");
  for (const ClaimRow& r : rows)
    std::printf("| %s | %s | %s | %s |\n", r.claim.c_str(), r.thesis.c_str(), r.measured.c_str(), r.verdict.c_str());
}

}  // namespace

int run_claims(const ConfigFiles& config, bool campaign_only) {
  const Params p = load_params(config);
  std::vector<ClaimRow> rows;
  if (campaign_only) {
    print_claims(campaign_claims());
    return 0;
  }
  dda_rows(p, rows);
  error_rows(p, rows);
  precision_rows(p, rows);
  numerics_rows(p, config, rows);
  thesis_rows(p, rows);
  memory_rows(p, rows);
  preparer_rows(p, rows);
  for (ClaimRow& r : campaign_claims()) rows.push_back(std::move(r));
  print_claims(rows);
  return 0;
}

}  // namespace girtd
