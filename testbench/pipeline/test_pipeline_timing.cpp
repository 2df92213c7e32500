// The SystemC pipeline's timing against expectations worked out by hand
// (a stage's time = its flops over its rate), against the bare back ends
// (the coupling must add no tick), and its timed front end against the
// untimed one. One simulation per TEST_CASE: SystemC elaborates once per
// process, and catch_discover_tests runs each case in its own.
#include <catch2/catch.hpp>

#include <random>

#include "backends/golden_backend.hpp"
#include "backends/render_session.hpp"
#include "dda/dda_preparer.hpp"
#include "engine/backend_registry.hpp"
#include "backends/front_end_runner.hpp"
#include "io/scene_reader.hpp"
#include "pipeline/pipeline.hpp"
#include "rtl/backend_rtl.hpp"
#include "backends/approx_backend.hpp"
#include "frontend/stage_costs.hpp"
#include "workloads/random_triangles.hpp"

namespace girtd {
namespace {

const StageStats& stage(const RunStats& s, const std::string& name) {
  for (const StageStats& st : s.stages)
    if (st.name == name) return st;
  FAIL("no stage " << name);
  throw;
}

// Small random triangles (at most 12 pixels across), one frame.
Trace small_triangles(int n, uint32_t seed) {
  std::mt19937 rng(seed);
  Trace t;
  t.path = "random";
  t.level = TraceLevel::kTriangle;
  t.frames.emplace_back();
  for (int i = 0; i < n; ++i) t.frames[0].triangles.push_back(random_triangle(rng, 12.0));
  return t;
}

// The same triangles prepared: a DDA-level trace (every set available at once).
Trace prepared(const Trace& tri, const Params& p) {
  Trace d;
  d.path = "prepared";
  d.level = TraceLevel::kDda;
  DdaPreparer prep(p);
  for (const TraceFrame& f : tri.frames) {
    TraceFrame out;
    out.settings = f.settings;
    DdaParams dp;
    for (const Triangle& t : f.triangles)
      if (prep.prepare(t, f.settings, dp) == PrepareResult::kReady) out.dda.push_back(dp);
    d.frames.push_back(out);
  }
  return d;
}

Params with(const std::string& json) { return Params::with_overrides(nlohmann::json::parse(json), "test"); }

}  // namespace

TEST_CASE("a slow preparer sets the pace: busy N x 115 flop / rate, the DDA starved between", "[pipeline]") {
  const double rate = 1e5;  // 1.15 ms per triangle
  const Params p = with(R"({"pipeline": {"flops_per_s": {"preparer": 1e5, "window_clip": 1e12}}})");
  const Trace trace = small_triangles(40, 3);
  FrameSource input(trace);
  const RenderOutput out = run_pipeline(backend_named("approx"), input, p, {});
  const RunStats& s = out.stats;
  const double per_triangle = 115.0 / rate;
  REQUIRE(preparer_ops(Params::defaults()).flops() == 115.0);
  // robust.json's options, by the breakdown in stage_costs.cpp: far edges
  // 3 x 10, the top-left rule 3 x (22 + 10 + a division of 4).
  const Params robust = Params::with_overrides(
      {{"preparer", {{"far_edges", "constant"}, {"fill_rule", "top_left"}, {"edge_flags", true}}}}, "test");
  CHECK(preparer_ops(robust).flops() == 115.0 + 30 + 108);
  CHECK(stage(s, "preparer").items == 40);
  CHECK(*stage(s, "preparer").busy_s == Approx(40 * per_triangle).epsilon(1e-9));
  REQUIRE(s.timing);
  // The run lasts the preparer's 40 triangles, plus the frame clear before
  // the first can be drawn and the last one's drawing (well under 0.1 ms).
  const double clear_s = 256 * (200 + 220) * 1e-9;
  CHECK(s.timing->modeled_s >= 40 * per_triangle);
  CHECK(s.timing->modeled_s <= 40 * per_triangle + clear_s + 1e-4);
  CHECK(s.timing->bottleneck == "preparer");
  // The DDA waits for every set but the time it spends drawing.
  CHECK(s.timing->dda_starved_s == Approx(s.timing->modeled_s - clear_s).margin(0.05 * s.timing->modeled_s));
  CHECK(s.timing->preparer_capacity_triangles_per_s == Approx(rate / 115.0));
}

TEST_CASE("a FIFO two deep blocks the stage before a slow one and never holds more than two", "[pipeline]") {
  const Params p = with(R"({"pipeline": {"fifo_depth": 2, "flops_per_s": {"preparer": 1e5, "window_clip": 1e12}}})");
  FrameSource input(small_triangles(30, 4));
  const RenderOutput out = run_pipeline(backend_named("approx"), input, p, {});
  const StageStats& clip = stage(out.stats, "window_clip");
  const StageStats& prep = stage(out.stats, "preparer");
  // The window clip finishes at once, then waits for the preparer to take
  // each triangle: blocked for nearly all of the preparer's time.
  CHECK(*clip.blocked_s == Approx(*prep.busy_s).margin(3 * 115.0 / 1e5));
  CHECK(*prep.fifo_in_max == 2);
  for (const StageStats& st : out.stats.stages)
    if (st.fifo_in_max && st.name != "had") CHECK(*st.fifo_in_max <= 2);
}

TEST_CASE("rtl in the pipeline takes exactly the bare Verilated back end's ticks", "[pipeline][rtl]") {
  const Params p = Params::defaults();
  const Trace dda = prepared(small_triangles(200, 5), p);
  BackendResult c;
  std::vector<uint8_t> bare_rgb;
  {  // one Verilated back end alive at a time (backend_rtl.hpp)
    const std::unique_ptr<BackendRtl> bare = make_backend_rtl(p);
    bare->begin_frame(dda.frames[0].settings);
    for (const DdaParams& d : dda.frames[0].dda) bare->draw(d);
    bare->end_frame();
    c = bare->result();
    bare_rgb = bare->shown().rgb;
  }

  FrameSource input(dda);
  const RenderOutput out = run_pipeline(backend_named("rtl"), input, p, {});
  REQUIRE(out.stats.timing);
  CHECK(out.stats.timing->modeled_s == Approx(double(c.ticks) * p.base_tick_ns * 1e-9).epsilon(1e-12));
  CHECK(out.stats.pixels_generated == c.pixels_generated);
  CHECK(out.stats.had.written == c.had.written);
  CHECK(out.stats.timing->page_misses == c.page_misses);
  CHECK(out.stats.timing->dda_starved_s == 0.0);
  CHECK(out.shown.rgb == bare_rgb);
}

TEST_CASE("approx in the pipeline takes exactly the bare approx back end's ticks", "[pipeline]") {
  const Params p = Params::defaults();
  const Trace dda = prepared(small_triangles(300, 6), p);
  const std::unique_ptr<Backend> bare = make_approx_backend(p, std::nullopt);
  bare->begin_frame(dda.frames[0].settings);
  for (const DdaParams& d : dda.frames[0].dda) bare->draw(d);
  bare->end_frame();
  const BackendResult c = bare->modeled_time()->result();

  FrameSource input(dda);
  const RenderOutput out = run_pipeline(backend_named("approx"), input, p, {});
  REQUIRE(out.stats.timing);
  CHECK(out.stats.timing->modeled_s == Approx(double(c.ticks) * p.base_tick_ns * 1e-9).epsilon(1e-12));
  CHECK(out.stats.pixels_generated == c.pixels_generated);
  CHECK(out.stats.timing->page_misses == c.page_misses);
  CHECK(out.shown.rgb == bare->shown().rgb);
}

TEST_CASE("the timed front end, stages working on different frames at once, gives the untimed one's frames", "[pipeline]") {
  const Params p = Params::defaults();
  const Trace polygons = read_scene("traces/scenes/animation.json", p);
  REQUIRE(polygons.frames.size() > 1);
  const FrontEndRun fe = run_front_end(polygons, p, PrunePlan{});
  RenderOptions keep;
  keep.keep_all_frames = true;
  FrameSource drawn_by_golden(fe.triangles);
  const RenderOutput want = render_frames(backend_named("golden"), drawn_by_golden, p, keep);

  FrameSource polygons_in(polygons);
  const RenderOutput got = run_pipeline(backend_named("approx"), polygons_in, p, keep);
  REQUIRE(got.stats.frontend);
  CHECK(got.stats.frontend->triangles_out == fe.counts.triangles_out);
  CHECK(got.stats.frontend->depth_sort_comparisons == fe.counts.depth_sort_comparisons);
  CHECK(got.stats.frontend->full_sorts == fe.counts.full_sorts);
  CHECK(got.stats.frontend->polygons == fe.counts.polygons);
  CHECK(got.stats.frames == polygons.frames.size());
  REQUIRE(got.per_frame.size() == want.per_frame.size());
  for (size_t i = 0; i < want.per_frame.size(); ++i) CHECK(got.per_frame[i].rgb == want.per_frame[i].rgb);
  // Lighting starts the second frame while the frame-long stages still hold
  // the first: it begins frame 1 before the depth sort has handed frame 0 on.
  const StageStats& lighting = stage(got.stats, "lighting");
  const StageStats& sort = stage(got.stats, "depth_sort");
  REQUIRE(lighting.frame_begin_s.size() == polygons.frames.size());
  REQUIRE(sort.frame_end_s.size() == polygons.frames.size());
  CHECK(lighting.frame_begin_s[1] < sort.frame_end_s[0]);
  CHECK(lighting.frame_begin_s[0] == 0.0);
}

}  // namespace girtd
