#include "rtl/timing_comparison.hpp"

#include <chrono>

#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"
#include "had/had.hpp"
#include "io/trace_reader.hpp"

namespace girtd {

TimingComparison compare_timing(const Params& p, const std::string& trace_path) {
  using clock = std::chrono::steady_clock;
  const Trace trace = read_trace(trace_path, std::nullopt, p);
  DdaPreparer prep(p);
  std::vector<std::vector<DdaParams>> frames;
  for (const TraceFrame& f : trace.frames) {
    frames.emplace_back(f.dda);
    DdaParams d;
    for (const Triangle& t : f.triangles)
      if (prep.prepare(t, f.settings, d) == PrepareResult::kReady) frames.back().push_back(d);
  }
  TimingComparison c;

  const auto t0 = clock::now();
  BackendTimingModel model(p);
  ModelSeries series(p, model);  // as the approx back end records them
  DdaEngine dda(p);
  FrameBuffer fb(p.screen_width, p.screen_height, uint16_t(p.depth_clear));
  Had had(fb, p.one_minus_nf);
  std::vector<TimedPixel> pixels;
  for (size_t i = 0; i < frames.size(); ++i) {
    fb.clear_back(trace.frames[i].settings.background);
    model.begin_frame();
    series.begin_frame();
    for (const DdaParams& d : frames[i]) {
      pixels.clear();
      const DdaRunStats st = dda.run(d, [&](const DdaEmit& e) {
        pixels.push_back({e.cycle, e.pixel.x, e.pixel.y, had.update(e.pixel)});
      });
      model.begin_triangle();
      for (const TimedPixel& px : pixels) {
        model.pixel(px);
        series.pixel(px.x, px.y);
      }
      model.end_triangle(st.cycles);
      series.end_triangle(st.cycles, st.emitted);
    }
    model.end_frame();
    fb.swap();
  }
  c.model = model.timing();
  c.model_fifo = series.fifo(c.model.ticks);
  c.model_maps = series.maps();
  // Made (and reset) outside the timed part, as the pipeline's is.
  const std::unique_ptr<BackendRtl> made = make_backend_rtl(p);
  BackendRtl& rtl = *made;
  rtl.record_screen_maps();
  const auto t1 = clock::now();
  for (size_t i = 0; i < frames.size(); ++i) {
    rtl.begin_frame(trace.frames[i].settings.background);
    for (const DdaParams& d : frames[i]) rtl.draw(d);
    rtl.end_frame();
  }
  c.rtl = rtl.result();
  // None recorded under GIRTD_NO_SERIES: then the RTL's series stays empty.
  if (const auto levels = rtl.fifo_levels(c.rtl.ticks)) c.rtl_fifo = *levels;
  c.rtl_maps = rtl.screen_maps();
  const auto t2 = clock::now();
  c.model_wall_s = std::chrono::duration<double>(t1 - t0).count();
  c.rtl_wall_s = std::chrono::duration<double>(t2 - t1).count();
  return c;
}

}  // namespace girtd
