// The back end's event timing model (models/timing) against the RTL back end
// (hw/backend) on the sample traces: the same page misses, and the modeled
// time within 2 % of the RTL's tick count (the approx back end's bar).
#include <catch2/catch.hpp>

#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"
#include "had/had.hpp"
#include "io/trace_reader.hpp"
#include "rtl/backend_rtl.hpp"
#include "timing/backend_timing.hpp"

namespace girtd {
namespace {

struct Compared {
  BackendTiming model;
  BackendCounters rtl;
};

Compared run_both(const std::string& path) {
  const Params p = Params::defaults();
  const Trace trace = read_trace(path, std::nullopt, p);
  BackendTimingModel model(p);
  BackendRtl rtl(p);
  DdaPreparer prep(p);
  DdaEngine dda(p);
  FrameBuffer fb(p.screen_width, p.screen_height, uint16_t(p.depth_clear));
  Had had(fb, p.one_minus_nf);
  for (const TraceFrame& f : trace.frames) {
    fb.clear_back(f.settings.background);
    model.begin_frame();
    rtl.begin_frame(f.settings.background);
    DdaParams d;
    for (const Triangle& t : f.triangles) {
      if (prep.prepare(t, f.settings, d) != PrepareResult::kReady) continue;
      std::vector<TimedPixel> pixels;
      const DdaRunStats st = dda.run(d, [&](const DdaEmit& e) {
        pixels.push_back({e.cycle, e.pixel.x, e.pixel.y, had.update(e.pixel)});
      });
      model.triangle(st.cycles, pixels);
      rtl.draw(d);
    }
    model.end_frame();
    rtl.end_frame();
    fb.swap();
  }
  return {model.timing(), rtl.counters()};
}

void check_trace(const std::string& path) {
  const Compared c = run_both(path);
  INFO(path << ": model " << c.model.ticks << " ticks, RTL " << c.rtl.ticks << "; misses " << c.model.page_misses
            << " / " << c.rtl.page_misses << "; DDA waits " << c.model.dda_wait_clocks << " / "
            << c.rtl.dda_wait_ticks / 7);
  CHECK(c.model.page_misses == c.rtl.page_misses);
  CHECK(c.model.pixels == c.rtl.pixels_generated);
  CHECK(c.model.dda_wait_clocks * 7 == c.rtl.dda_wait_ticks);  // 7 ticks per DDA clock (35 ns / 5 ns)
  CHECK(std::abs(double(c.model.ticks) - double(c.rtl.ticks)) <= 0.02 * double(c.rtl.ticks));
  // Measured: within 20 ticks per trace (the frame-end handshakes); hold it there.
  CHECK(std::abs(double(c.model.ticks) - double(c.rtl.ticks)) <= 32.0);
}

}  // namespace

TEST_CASE("timing model matches the RTL back end: 200-pixel triangles", "[timing]") {
  check_trace("traces/equilateral_200.trace");
}
TEST_CASE("timing model matches the RTL back end: z_overlap", "[timing]") { check_trace("traces/z_overlap.trace"); }
TEST_CASE("timing model matches the RTL back end: transparent (blends)", "[timing]") {
  check_trace("traces/transparent.trace");
}
TEST_CASE("timing model matches the RTL back end: slivers", "[timing]") { check_trace("traces/sliver_fan.trace"); }
TEST_CASE("timing model matches the RTL back end: demo", "[timing]") { check_trace("traces/demo.trace"); }

}  // namespace girtd
