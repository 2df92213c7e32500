#include "backends/front_end_runner.hpp"

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

FrontEndRunner::FrontEndRunner(const Params& params, const PrunePlan& prune)
    : fe_(ScreenMap{params.screen_width, params.screen_height}, params.depth_max_mapped,
          front_end_options(params, prune)) {
  count_front_end_pass();
}

void FrontEndRunner::show_progress() {
  fe_.on_progress([](size_t done, size_t total) { ProgressLine::get().step("front end", done, total, "polygons"); });
}

FrontEndRun run_front_end(const Trace& polygons, const Params& params, const PrunePlan& prune) {
  FrontEndRunner fe(params, prune);
  FrontEndRun run;
  run.triangles.path = polygons.path;
  run.triangles.level = TraceLevel::kTriangle;
  for (const TraceFrame& in : polygons.frames) {
    TraceFrame out;
    out.settings = in.settings;
    out.triangles = fe.run(in.world, in.settings);
    run.triangles.frames.push_back(std::move(out));
  }
  run.counts = fe.counts();
  return run;
}

}  // namespace girtd
