#include "frontend/front_end_runner.hpp"

#include "frontend/front_end.hpp"

namespace girtd {

FrontEndRun run_front_end(const Trace& polygons, const Params& params) {
  FrontEnd fe(ScreenMap{params.screen_width, params.screen_height}, params.depth_max_mapped);
  FrontEndRun run;
  run.triangles.path = polygons.path;
  run.triangles.level = TraceLevel::kTriangle;
  for (const TraceFrame& in : polygons.frames) {
    TraceFrame out;
    out.settings = in.settings;
    for (const FrontTriangle& t : fe.run_frame(in.world, in.settings.window)) out.triangles.push_back(t.tri);
    run.triangles.frames.push_back(std::move(out));
  }
  run.counts = fe.counts();
  return run;
}

}  // namespace girtd
