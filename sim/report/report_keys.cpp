#include "report/report_keys.hpp"

#include <sstream>

#include "dda/dda_engine.hpp"
#include "frontend/stage_costs.hpp"

namespace girtd {

using nlohmann::json;

namespace {

template <typename T>
json opt(const std::optional<T>& v) {
  return v ? json(*v) : json(nullptr);
}

double per_s(double count, double seconds) { return seconds > 0 ? count / seconds : 0.0; }

using Value = std::function<json(const ReportSource&)>;
using StageValue = std::function<json(const ReportSource&, const StageStats&)>;

ReportKey key(std::string path, std::string unit, std::string meaning, unsigned known_by, Value value,
              bool summary = false) {
  return {std::move(path), std::move(unit), std::move(meaning), known_by, summary, std::move(value), {}};
}

ReportKey stage_key(const std::string& leaf, std::string unit, std::string meaning, unsigned known_by,
                    StageValue value) {
  return {"stages.*." + leaf, std::move(unit), std::move(meaning), known_by, false, {}, std::move(value)};
}

// report.json `numerics` (dda/ep_numerics.hpp), clamps from the preparer.
json numerics_json(const ReportSource& r) {
  if (!r.s.dda || r.ctx.level == "thesis") return json();  // the appendix program's registers are its own
  const EpNumerics& n = r.s.dda->numerics;
  json out;
  for (int i = 0; i < kEpCount; ++i)
    out[kEpNames[i]] = {{"wraps", n.ep[i].wraps},
                        {"saturations", n.ep[i].saturations},
                        {"clamps", r.s.preparer ? r.s.preparer->clamps[i] : 0}};
  out["triangles_affected"] = n.triangles_affected;
  out["first_triangle_affected"] = n.first_affected ? json(n.first_affected) : json();
  return out;
}

// Keys of the whole-pipeline timing (the timed back ends).
const PipelineTiming& timing(const ReportSource& r) { return *r.s.timing; }
double pixels(const ReportSource& r) { return double(r.s.pixels_generated); }
double modeled_mpixels(const ReportSource& r) { return per_s(pixels(r), timing(r).modeled_s) / 1e6; }
std::optional<double> sustained_mpixels(const ReportSource& r) {
  const auto& s = timing(r).sustained_pixels_per_s;
  return s ? std::optional<double>(*s / 1e6) : std::nullopt;
}
// What target_met and the PASS / FAIL line judge.
double judged_mpixels(const ReportSource& r) { return sustained_mpixels(r).value_or(modeled_mpixels(r)); }

// A front-end count: null when the input entered below the front end.
ReportKey frontend_key(const std::string& leaf, std::string meaning, uint64_t FrontendCounts::*field) {
  return key("frontend." + leaf, "count", std::move(meaning), kEvery,
             [field](const ReportSource& r) { return json((*r.s.frontend).*field); });
}

ReportKey preparer_key(const std::string& leaf, std::string meaning, uint64_t PreparerCounts::*field) {
  return key("preparer." + leaf, "count", std::move(meaning), kHardware,
             [field](const ReportSource& r) { return json((*r.s.preparer).*field); });
}

std::vector<ReportKey> make_keys() {
  std::vector<ReportKey> k = {
      key("backend", "—", "the back end that ran", kEvery, [](auto& r) { return json(r.ctx.backend); }, true),
      key("input", "—", "the input file", kEvery, [](auto& r) { return json(r.ctx.input); }, true),
      key("level", "—", "the input's level (`polygon` for models, scenes and polygon traces)", kEvery,
          [](auto& r) { return json(r.ctx.level); }, true),
      key("frames", "count", "frames rendered", kEvery, [](auto& r) { return json(r.s.frames); }, true),
      key("triangles_in", "count", "primitives entering the back end", kEvery,
          [](auto& r) { return json(r.s.triangles_in); }, true),
      key("triangles_drawn", "count",
          "triangles that reached the DDA (not degenerate, inside the window, at least one lattice row)", kEvery,
          [](auto& r) { return json(r.s.triangles_drawn); }, true),
      key("pixels_generated", "count", "pixel-emitting DDA clocks (reference: pixels it emits)", kEvery,
          [](auto& r) { return json(r.s.pixels_generated); }, true),
      key("pixels_written", "count", "R, G, B and Z written (nf = 1, Z < Zb)", kEvery,
          [](auto& r) { return json(r.s.had.written); }, true),
      key("pixels_blended", "count", "R, G, B blended, Z kept (0 < nf < 1)", kEvery,
          [](auto& r) { return json(r.s.had.blended); }, true),
      key("pixels_z_rejected", "count", "failed Z < Zb", kEvery, [](auto& r) { return json(r.s.had.z_rejected); },
          true),
      key("pixels_reblended", "count",
          "seams: blends of a pixel that its surface's faces turned the same way had already blended in this "
          "frame, one of the two inside its triangle (a shared edge drawn by both triangles, or a neighbour's "
          "antialiasing fringe over a triangle; two fringes over each other outside a silhouette's corner are "
          "per-edge antialiasing and not counted); the run warns. 0 with "
          "`preparer.fill_rule` top_left and `preparer.edge_flags` (config/presets/robust.json). Needs the "
          "triangles' surfaces (polygon-level input, or triangle traces that carry them). Not on rtl: its HAD "
          "sees no surface ids",
          kSurfaces, [](auto& r) { return json(r.s.had.reblended); }),
      key("pixels_dropped", "count",
          "nf = 0 or off-screen. generated = written + blended + z_rejected + dropped", kEvery,
          [](auto& r) { return json(r.s.had.dropped); }, true),
      key("dda_cycles", "DDA clocks", "every state, emitting or not", kHardware,
          [](auto& r) { return r.s.dda ? json(r.s.dda->cycles) : json(); }, true),
      key("dda_efficiency", "ratio", "emitting clocks / all clocks", kHardware,
          [](auto& r) {
            if (!r.s.dda) return json();
            return json(r.s.dda->cycles ? double(r.s.dda->emitted) / double(r.s.dda->cycles) : 0.0);
          },
          true),
      key("dda_bound_time_s", "s", "`dda_cycles` x `clock_ns`: the DDA alone, no memory side", kHardware,
          [](auto& r) { return r.s.dda ? json(double(r.s.dda->cycles) * r.params.dda_clock_ns * 1e-9) : json(); }),
      key("dda_bound_mpixels_per_s", "Mpixel/s", "generated pixels / `dda_bound_time_s`", kHardware,
          [](auto& r) {
            if (!r.s.dda) return json();
            const double t = double(r.s.dda->cycles) * r.params.dda_clock_ns * 1e-9;
            return json(t > 0 ? double(r.s.dda->emitted) / t / 1e6 : 0.0);
          },
          true),
      key("dda_states", "clocks", "clocks spent in each state, by state name (`models/dda/README.md`)", kHardware,
          [](auto& r) {
            if (!r.s.dda) return json();
            json states;
            for (int i = 0; i < static_cast<int>(DdaState::kCount); ++i) states[kDdaStateNames[i]] = r.s.dda->per_state[i];
            return states;
          }),
      key("numerics", "count",
          "per EP (`R` ... `D3`): `wraps` (uses of a wrapped register: D1..D3 at every clock that tests the edges, "
          "R, G, B, T, Z at every pixel emitted. The adders are modular, so a value that wraps and steps back is "
          "right again and not counted; a counted one changes the picture, and the run warns), "
          "`saturations` (outputs clipped at emission, by design), "
          "`clamps` (start values and derivatives the preparer clamped); `triangles_affected` (drawn with a wrap "
          "or a clamp; the run warns for either) and `first_triangle_affected` (numbered from 1 among those drawn, "
          "over all frames; null: none). A wrap is what the detector sees: each EP carried with "
          "`ep.wrap_guard_bits` guard bits (golden and the RTL alike, hw/dda/dda_limits.sv). null on thesis-level "
          "traces (the appendix program's own formats)",
          kHardware, [](auto& r) { return numerics_json(r); }),
      key("clock_ns", "ns", "DDA clock period", kEvery, [](auto& r) { return json(r.params.dda_clock_ns); }, true),
      key("modeled_time_s", "s",
          "whole-pipeline modeled time, from the first frame's clear to the last swap", kTimed,
          [](auto& r) { return json(timing(r).modeled_s); }, true),
      key("modeled_mpixels_per_s", "Mpixel/s", "generated pixels over `modeled_time_s`", kTimed,
          [](auto& r) { return json(modeled_mpixels(r)); }, true),
      key("target_mpixels_per_s", "Mpixel/s", "the thesis' 20", kEvery,
          [](auto& r) { return json(r.params.target_mpixels_per_s); }, true),
      key("sustained_mpixels_per_s", "Mpixel/s",
          "the pixels of frames 2..N over the modeled time from frame 1's swap to frame N's: the rate with the "
          "pipeline full, as the thesis' 20 Mpixel/s is meant (`render --repeat N` draws a static input N times); "
          "null for one frame",
          kTimed, [](auto& r) { return sustained_mpixels(r) ? json(*sustained_mpixels(r)) : json(); }, true),
      key("target_met", "bool",
          "the judged rate >= the target: `sustained_mpixels_per_s` when not null, else `modeled_mpixels_per_s` "
          "(report.md: PASS / FAIL line)",
          kTimed, [](auto& r) { return json(judged_mpixels(r) >= r.params.target_mpixels_per_s); }),
      key("back_end_mpixels_per_s", "Mpixel/s",
          "generated pixels over the modeled time less `time_split.dda_starved_s`: the rate with the DDA always fed",
          kTimed, [](auto& r) { return json(per_s(pixels(r), timing(r).modeled_s - timing(r).dda_starved_s) / 1e6); }),
      key("bottleneck", "stage name",
          "the stage with the most busy time. A DDA starved by a frame-long stage (projection, sort) shows in "
          "`time_split.dda_starved_s`, not here",
          kTimed, [](auto& r) { return json(timing(r).bottleneck); }, true),
      key("cache.accesses", "count", "accesses to the pixel cache: every generated pixel is one", kTimed,
          [](auto& r) { return json(timing(r).cache_accesses); }),
      key("cache.page_misses", "count", "accesses whose page was not in the cache", kTimed,
          [](auto& r) { return json(timing(r).page_misses); }),
      key("cache.nac", "accesses/page", "accesses per page miss", kTimed,
          [](auto& r) {
            const PipelineTiming& t = timing(r);
            return json(t.page_misses ? double(t.cache_accesses) / double(t.page_misses) : 0.0);
          }),
      key("time_split.dda_busy_s", "s", "where the time went: DDA clocks on triangles", kTimed,
          [](auto& r) { return json(timing(r).dda_busy_s); }),
      key("time_split.dda_fifo_full_s", "s", "the DDA waiting on a full DDA -> HAD FIFO", kTimed,
          [](auto& r) { return json(timing(r).dda_fifo_full_s); }),
      key("time_split.dda_starved_s", "s", "the DDA idle with no parameter set (the front end starving it)", kTimed,
          [](auto& r) { return json(timing(r).dda_starved_s); }),
      key("time_split.had_page_wait_s", "s",
          "the HAD waiting on page write-backs and fetches (while the DDA runs: it overlaps the three before; the "
          "parts need not add up to `modeled_time_s`)",
          kTimed, [](auto& r) { return json(timing(r).had_page_wait_s); }),
      key("time_split.frame_clear_swap_s", "s", "clearing frames, and writing the cache back and swapping at their ends",
          kTimed, [](auto& r) { return json(timing(r).frame_clear_swap_s); }),
      key("preparer_triangles_per_s", "triangles/s",
          "parameter sets the preparer delivered over the modeled time (null: no preparer ran)", kTimed,
          [](auto& r) {
            return r.s.preparer ? json(per_s(double(timing(r).preparer_triangles), timing(r).modeled_s)) : json();
          }),
      key("preparer_capacity_triangles_per_s", "triangles/s", "its rate over its flops per triangle", kTimed,
          [](auto& r) { return r.s.preparer ? json(timing(r).preparer_capacity_triangles_per_s) : json(); }),
      key("target_preparer_triangles_per_s", "triangles/s", "the thesis' 40,000", kTimed,
          [](auto& r) { return r.s.preparer ? json(r.params.target_preparer_triangles_per_s) : json(); }),
      stage_key("items", "count", "items the stage took in", kEvery, [](auto&, auto& st) { return json(st.items); }),
      stage_key("busy_s", "s", "computing", kTimed, [](auto&, auto& st) { return opt(st.busy_s); }),
      stage_key("stall_s", "s", "`starved_s` + `blocked_s`", kTimed, [](auto&, auto& st) { return opt(st.stall_s); }),
      stage_key("starved_s", "s", "waiting for input", kTimed, [](auto&, auto& st) { return opt(st.starved_s); }),
      stage_key("blocked_s", "s",
                "waiting for room in the next FIFO (dda: on the full DDA -> HAD FIFO; had: none, its page waits are "
                "busy time)",
                kTimed, [](auto&, auto& st) { return opt(st.blocked_s); }),
      stage_key("flops", "flop", "arithmetic done (front-end stages, preparer; `sim/frontend/README.md`)", kTimed,
                [](auto&, auto& st) { return opt(st.flops); }),
      stage_key("fifo_in_max", "items",
                "most items (frame markers included) ever in the FIFO in front of the stage; dda: the preparer -> "
                "DDA FIFO; had: the DDA -> HAD FIFO (pixels)",
                kTimed, [](auto&, auto& st) { return opt(st.fifo_in_max); }),
      stage_key("utilization", "ratio", "`busy_s` / `modeled_time_s`", kTimed,
                [](auto& r, auto& st) {
                  return st.busy_s && timing(r).modeled_s > 0 ? json(*st.busy_s / timing(r).modeled_s) : json();
                }),
      key("stage_order", "list", "the stages in pipeline order", kEvery,
          [](auto& r) {
            json order = json::array();
            for (const StageStats& st : r.s.stages) order.push_back(st.name);
            return order;
          }),
      key("preparer", "—", "the preparer's verdicts (null: no preparer ran)", kHardware,
          [](auto& r) { return r.s.preparer ? json::object() : json(); }),
      preparer_key("prepared", "parameter sets handed to the DDA", &PreparerCounts::prepared),
      preparer_key("degenerate", "triangles without area", &PreparerCounts::degenerate),
      preparer_key("off_window",
                   "triangles without a start point in the window (with `preparer.far_edges` constant, also "
                   "those wholly outside an edge over the pixel box)",
                   &PreparerCounts::off_window),
      preparer_key("constant_edges", "edges sent as constants (`preparer.far_edges` constant: the line misses the pixel box)",
                   &PreparerCounts::constant_edges),
      preparer_key("limited_planes",
                   "attribute planes cut across their triangle's longest edge (`preparer.steep_attributes` limited: "
                   "the EP would have left its format in the pixel box the DDA walks)",
                   &PreparerCounts::limited_planes),
      preparer_key("no_lattice_row", "triangles crossing no pixel row", &PreparerCounts::no_lattice_row),
      key("preparer.clamped_values", "count", "start values or derivatives that did not fit their EP (per EP: "
          "`numerics`)", kHardware, [](auto& r) { return json(r.s.preparer->clamped_values()); }),
      key("frontend", "—",
          "the front end's counts summed over frames (`models/frontend/README.md`); null when the input entered "
          "below the front end (a `triangle` or `dda` trace)",
          kEvery, [](auto& r) { return r.s.frontend ? json::object() : json(); }),
      frontend_key("polygons", "polygons in", &FrontendCounts::polygons),
      frontend_key("objects", "objects in (a scene's models; a polygon trace's `object` groups)", &FrontendCounts::objects),
      frontend_key("objects_culled", "objects whose bounding sphere misses the view volume (`culling.objects`)",
                   &FrontendCounts::objects_culled),
      frontend_key("object_culled_polygons", "their polygons, removed before lighting", &FrontendCounts::object_culled_polygons),
      frontend_key("culled", "back faces culled (the input's cull flag, or `culling.back_faces` always)",
                   &FrontendCounts::culled),
      frontend_key("back_faces_exempt",
                   "back faces of transparent surfaces `culling.back_faces` always kept (warned)",
                   &FrontendCounts::back_faces_exempt),
      key("frontend.culling_flops_saved", "flop",
          "what the polygons culling removed would have cost in lighting, view and the depth clip's test "
          "(`sim/frontend/stage_costs.hpp` culled_ops); the tests themselves are in `stages.culling.flops`, or in "
          "`stages.lighting.flops` where the config builds no culling stage (`culling.objects` false, "
          "`culling.back_faces` not always)",
          kEvery, [](auto& r) {
            const FrontendCounts& f = *r.s.frontend;
            return json(culled_ops(f.object_culled_polygons, f.object_culled_corners, f.object_culled_corner_lights).flops() +
                        culled_ops(f.culled, f.culled_corners, f.culled_corner_lights).flops());
          }),
      frontend_key("clipped", "polygons cut at Zs = C", &FrontendCounts::clipped),
      frontend_key("clipped_away", "polygons wholly at Zs <= C", &FrontendCounts::clipped_away),
      frontend_key("degenerate_polygons",
                   "no area: < 3 distinct corners or 2 x area <= 1e-12 perimeter^2, at input (of the objects culling kept; never back-face culled) or "
                   "after the depth clip",
                   &FrontendCounts::degenerate_polygons),
      frontend_key("non_planar", "polygons not in one plane", &FrontendCounts::non_planar),
      frontend_key("concave", "polygons with >= 1 concave vertex", &FrontendCounts::concave),
      frontend_key("ear_clipped", "polygons with >= 2 concave vertices (ear clipping)", &FrontendCounts::ear_clipped),
      frontend_key("triangulation_fallbacks", "self-intersecting polygons", &FrontendCounts::triangulation_fallbacks),
      frontend_key("triangles_made", "by the triangulator", &FrontendCounts::triangles_made),
      frontend_key("made_edges", "diagonals the triangulator made (invisible in wire-frame)", &FrontendCounts::made_edges),
      frontend_key("degenerate_triangles", "no screen area", &FrontendCounts::degenerate_triangles),
      frontend_key("discarded_off_window", "no start point (docs/design.md §3)", &FrontendCounts::discarded_off_window),
      frontend_key("triangles_out", "to the preparer", &FrontendCounts::triangles_out),
      frontend_key("depth_sort_comparisons", "comparisons the depth sort made", &FrontendCounts::depth_sort_comparisons),
      frontend_key("full_sorts", "frames sorted from scratch", &FrontendCounts::full_sorts),
      key("frontend_passes", "count",
          "times the front end ran over the input in this render: 1 for models, scenes and polygon traces on every "
          "back end (golden and reference run it before drawing, approx and rtl as their pipeline's stages; "
          "`--dump` and the progress line take what that one run made), 0 for triangle and DDA traces",
          kEvery, [](auto& r) { return json(r.ctx.front_end_passes); }),
      key("wall_s", "s", "host wall time of the render: the back end's, with the front end's stages on approx and "
          "rtl; golden's and reference's front end, placing a scene's frames and writing `--frames all` pictures "
          "are left out", kEvery, [](auto& r) { return json(r.s.wall_s); }, true),
      key("image_sha256", "hex", "SHA-256 of the displayed buffer's raw RGB bytes (screen width x height x 3, row by row)", kEvery,
          [](auto& r) { return json(r.ctx.image_sha256); }, true),
      key("not_modeled", "list", "the registered keys this back end cannot know (their values are null)", kEvery,
          [](auto& r) { return json(not_modeled_keys(r.ctx.capabilities)); }),
      key("warnings", "list of text",
          "input the run went on from, each `FILE: what` and also printed on stderr as `warning: FILE: what` (a "
          "model's missing `.mtl`, an unknown material: `sim/io/README.md`); empty when there were none",
          kEvery, [](auto& r) { return json(r.ctx.warnings); }),
      key("left_out", "list",
          "what the simulator skipped computing in this run, `{\"unit\", \"reason\"}` each, the reason saying "
          "how much (`sim/backends/prune_plan.hpp`): nothing the outputs depend on; empty with `render --no-prune`",
          kEvery, [](auto& r) {
            json out = json::array();
            for (const LeftOut& l : r.ctx.left_out) out.push_back({{"unit", l.unit}, {"reason", l.reason}});
            return out;
          }),
      key("sampling", "JSON",
          "approx with `render --sample-timing RATE` only (else null): a timing estimate, not a simulation of every "
          "triangle (`sim/backends/sampled_timing.hpp`): `rate`, triangles `measured`, `warmed` and `skipped` (not "
          "drawn: the frame is incomplete), `skipped_s` (the time charged for the skipped ones) and `ci_half_s` (its "
          "99.7 % confidence half-width)",
          kSampled, [](auto& r) {
            if (!r.s.sampling) return json();
            const SamplingStats& m = *r.s.sampling;
            const double tick_s = r.params.base_tick_ns * 1e-9;
            return json{{"rate", m.rate}, {"measured", m.measured}, {"warmed", m.warmed}, {"skipped", m.skipped},
                        {"skipped_s", m.skipped_ticks * tick_s}, {"ci_half_s", m.ci_half_ticks * tick_s}};
          }),
      key("config", "JSON", "the configuration used (`config/girtd.json` plus every `--config`)", kEvery,
          [](auto& r) { return r.params.source; }),
      key("rtl_build", "text",
          "rtl only (else null): the key of the RTL elaboration that ran, 16 hex digits of the configuration values "
          "the Verilated RTL is built for (`models/layout/rtl_package.hpp`); another configuration runs in an RTL "
          "variant built for it (`sim/rtl/rtl_variants.hpp`)",
          kEvery, [](auto& r) { return r.ctx.rtl_build.empty() ? json() : json(r.ctx.rtl_build); }),
  };
  return k;
}

std::string known_by_text(unsigned k, const std::vector<BackendEntry>& backends) {
  if (k == kEvery) return "all";
  std::string out;
  for (const BackendEntry& b : backends)
    if ((b.capabilities & k) == k) out += (out.empty() ? "" : ", ") + b.name;
  return out;
}

}  // namespace

const std::vector<ReportKey>& report_keys() {
  static const std::vector<ReportKey> keys = make_keys();
  return keys;
}

std::vector<std::string> not_modeled_keys(unsigned capabilities) {
  std::vector<std::string> out;
  for (const ReportKey& k : report_keys())
    if (!k.known_to(capabilities)) out.push_back(k.path);
  return out;
}

std::string report_keys_markdown(const std::vector<BackendEntry>& backends) {
  std::ostringstream o;
  o << "| key | unit | known by | meaning |\n|---|---|---|---|\n";
  for (const ReportKey& k : report_keys())
    o << "| `" << k.path << "` | " << k.unit << " | " << known_by_text(k.known_by, backends) << " | " << k.meaning << " |\n";
  return o.str();
}

}  // namespace girtd
