#include "rtl/timing_comparison.hpp"

#include <chrono>
#include <memory>
#include <vector>

#include "backends/approx_backend.hpp"
#include "dda/dda_preparer.hpp"
#include "io/trace_reader.hpp"
#include "rtl/backend_rtl.hpp"
#include "timeline/series_switch.hpp"

namespace girtd {
namespace {

using Frames = std::vector<std::vector<DdaParams>>;

// The trace's frames through one back end (made outside the timed part);
// its wall time.
double draw_frames(Backend& backend, const FrameSource& input, const Frames& frames) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  backend.begin(input);
  for (size_t i = 0; i < frames.size(); ++i) {
    backend.begin_frame(input.settings()[i]);
    for (const DdaParams& d : frames[i]) backend.draw(d);
    backend.end_frame();
  }
  return std::chrono::duration<double>(clock::now() - t0).count();
}

}  // namespace

TimingComparison compare_timing(const Params& p, const std::string& trace_path) {
  FrameSource input(read_trace(trace_path, std::nullopt, p));
  DdaPreparer prep(p);
  Frames frames;  // every frame's DDA sets, made before the timed part
  for (size_t i = 0; i < input.frames(); ++i) {
    const TraceFrame f = input.take(i);
    frames.emplace_back(f.dda);
    DdaParams d;
    for (const Triangle& t : f.triangles)
      if (prep.prepare(t, f.settings, d) == PrepareResult::kReady) frames.back().push_back(d);
  }
  TimingComparison c;
  {
    const std::unique_ptr<Backend> approx = make_approx_backend(p, std::nullopt);
    c.model_wall_s = draw_frames(*approx, input, frames);
    const ModeledTime& time = *approx->modeled_time();
    c.model = time.result();
    c.model_fifo = time.fifo_levels(c.model.ticks);
    c.model_maps = time.screen_maps();
  }
  const std::unique_ptr<BackendRtl> rtl = make_backend_rtl(p);
  if (record_series()) rtl->record_screen_maps();
  c.rtl_wall_s = draw_frames(*rtl, input, frames);
  c.rtl = rtl->result();
  c.rtl_fifo = rtl->fifo_levels(c.rtl.ticks);
  c.rtl_maps = rtl->screen_maps();
  return c;
}

}  // namespace girtd
