#include "rtl/memory_measurements.hpp"

#include "dda/dda_preparer.hpp"
#include "io/trace_reader.hpp"
#include "rtl/backend_rtl.hpp"

namespace girtd {
namespace {

// A parameter set the DDA emits without a wasted state per pixel on a row:
// all three distances a constant +1 (always inside), flat colour and depth.
DdaParams stream_params(const Params& p, PixelStream s) {
  DdaParams d;
  d.q = 0;
  if (s == PixelStream::kRow) {
    d.x0 = 0, d.y0 = 100, d.xmin = 0, d.xmax = 1023, d.ymax = 100;
  } else {
    d.x0 = 500, d.y0 = 0, d.xmin = 500, d.xmax = 500, d.ymax = 1023;
  }
  for (int e = kEpD1; e <= kEpD3; ++e) d.ep[e].v = p.ep_d.one();
  d.ep[kEpR].v = 200 * p.ep_color.one();
  d.ep[kEpG].v = 100 * p.ep_color.one();
  d.ep[kEpB].v = 50 * p.ep_color.one();
  d.ep[kEpT].v = 256 * p.ep_t.one();
  d.ep[kEpZ].v = 1000 * p.ep_z.one();
  return d;
}

}  // namespace

StreamTiming time_stream(const Params& p, PixelStream s) {
  const std::unique_ptr<BackendRtl> rtl = make_backend_rtl(p);
  BackendRtl& be = *rtl;
  be.begin_frame(Rgb{});
  const BackendResult start = be.result();
  be.draw(stream_params(p, s));
  be.drain();
  const BackendResult end = be.result();
  StreamTiming t;
  t.pixels = end.pixels_generated - start.pixels_generated;
  t.page_misses = end.page_misses - start.page_misses;
  t.ns_per_pixel = double(end.ticks - start.ticks) * p.base_tick_ns / double(t.pixels);
  return t;
}

double frame_clear_us(const Params& p) {
  const std::unique_ptr<BackendRtl> rtl = make_backend_rtl(p);
  BackendRtl& be = *rtl;
  const uint64_t t0 = be.now_tick();
  be.begin_frame(Rgb{});
  return double(be.now_tick() - t0) * p.base_tick_ns * 1e-3;
}

TraceTiming time_trace(const Params& p, const std::string& path) {
  const Trace trace = read_trace(path, std::nullopt, p);
  const std::unique_ptr<BackendRtl> rtl = make_backend_rtl(p);
  BackendRtl& be = *rtl;
  DdaPreparer prep(p);
  TraceTiming t;
  uint64_t ticks = 0;
  const BackendResult first = be.result();
  for (const TraceFrame& f : trace.frames) {
    be.begin_frame(f.settings.background);
    const uint64_t t0 = be.now_tick();
    DdaParams d;
    for (const Triangle& tri : f.triangles)
      if (prep.prepare(tri, f.settings, d) == PrepareResult::kReady) be.draw(d);
    for (const DdaParams& dd : f.dda) be.draw(dd);
    be.drain();
    ticks += be.now_tick() - t0;
    be.end_frame();
  }
  const BackendResult end = be.result();
  t.pixels = end.pixels_generated - first.pixels_generated;
  t.seconds = double(ticks) * p.base_tick_ns * 1e-9;
  const double waited = double(end.dda_wait_ticks - first.dda_wait_ticks) / p.ticks(p.dda_clock_ns);
  const double worked = double(end.dda.cycles - first.dda.cycles);
  t.dda_wait_fraction = worked + waited > 0 ? waited / (worked + waited) : 0;
  t.fifo_max = end.fifo_max;
  const uint64_t misses = end.page_misses - first.page_misses;
  t.nac = misses ? double(end.had.total() - first.had.total()) / double(misses) : 0;
  return t;
}

}  // namespace girtd
