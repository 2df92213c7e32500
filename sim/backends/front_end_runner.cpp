#include "backends/front_end_runner.hpp"

#include "frontend/front_end.hpp"
#include "io/progress_line.hpp"

namespace girtd {

namespace {
uint64_t passes = 0;
}  // namespace

uint64_t front_end_passes() { return passes; }
void count_front_end_pass() { ++passes; }

FrontEndOptions front_end_options(const Params& params, const PrunePlan& plan) {
  FrontEndOptions o;
  o.cull_objects = params.cull_objects;
  o.cull_back_faces_always = params.cull_back_faces_always;
  o.prune_lighting_out_of_view = plan.lighting_out_of_view;
  return o;
}

namespace {

// `release`: the same trace as `polygons`, each frame's polygons released as it is done.
FrontEndRun front_end_over(const Trace& polygons, const Params& params, const PrunePlan& prune, Trace* release) {
  count_front_end_pass();
  FrontEnd fe(ScreenMap{params.screen_width, params.screen_height}, params.depth_max_mapped,
              front_end_options(params, prune));
  FrontEndRun run;
  run.triangles.path = polygons.path;
  run.triangles.level = TraceLevel::kTriangle;
  // The progress line counts polygons over every frame.
  uint64_t all = 0, before = 0;
  for (const TraceFrame& in : polygons.frames) all += in.world.polygons.size();
  fe.on_progress([&](size_t done, size_t) { ProgressLine::get().step("front end", before + done, all, "polygons"); });
  for (size_t i = 0; i < polygons.frames.size(); ++i) {
    const TraceFrame& in = polygons.frames[i];
    TraceFrame out;
    out.settings = in.settings;
    const size_t count = in.world.polygons.size();
    out.triangles = release ? fe.run_frame_releasing(release->frames[i].world, in.settings.window, in.settings.q)
                            : fe.run_frame(in.world, in.settings.window, in.settings.q);
    run.triangles.frames.push_back(std::move(out));
    before += count;
  }
  run.counts = fe.counts();
  return run;
}

}  // namespace

FrontEndRun run_front_end(const Trace& polygons, const Params& params, const PrunePlan& prune) {
  return front_end_over(polygons, params, prune, nullptr);
}

FrontEndRun run_front_end_releasing(Trace& polygons, const Params& params, const PrunePlan& prune) {
  return front_end_over(polygons, params, prune, &polygons);
}

}  // namespace girtd
