#include "backends/render_session.hpp"

#include "common/input_error.hpp"
#include "dda/dda_preparer.hpp"
#include "backends/dump_tap.hpp"
#include "backends/frame_driver.hpp"

namespace girtd {

RgbImage shown_image(const FrameBuffer& fb) {
  RgbImage img;
  img.width = fb.width();
  img.height = fb.height();
  img.rgb = fb.shown_bytes();
  return img;
}

RenderOutput render_trace(const Trace& trace, Backend& backend, const Params& params, const RenderOptions& opt) {
  backend.prune(opt.prune);
  backend.begin(trace);
  // --dump: the input as it came, the front end's triangles as drawn, or the
  // DDA parameter sets as the back end draws them.
  const Trace& input = opt.polygon_source ? *opt.polygon_source : trace;
  FrameDriver driver(backend.name(), input, params, opt);
  DumpTap* tap = driver.tap();
  const bool dda_tap = tap && tap->level() == TraceLevel::kDda;
  if (dda_tap && !backend.tap_dda([tap](const DdaParams& d) { tap->write(d); }))
    throw InputError(opt.dump->path, 0, "the " + backend.name() + " back end has no DDA: dump dda from golden, approx or rtl");

  // The video memory exists before the run starts, as the hardware's does
  // (and as llvmpipe's buffer in the golden speed bench): allocating and
  // first touching its 12 MB is not drawing. Each frame's clear is timed.
  FrameBuffer fb(params.screen_width, params.screen_height, static_cast<uint16_t>(params.depth_clear));
  Had had(fb, params.one_minus_nf);
  driver.start();
  RenderOutput out;
  // The thesis program draws a 128 x 96 picture in the frame's top-left corner.
  if (trace.level == TraceLevel::kThesis) had.set_screen(params.thesis.width, params.thesis.height);
  const size_t n_frames = trace.frames.size();
  for (size_t i = 0; i < n_frames; ++i) {
    const TraceFrame& f = trace.frames[i];
    if (dda_tap) tap->begin_frame(f.settings);
    else if (tap) tap->frame(tap->level() == TraceLevel::kPolygon ? input.frames[i] : f);
    fb.clear_back(f.settings.background);
    had.set_drop_partial(f.settings.qq);
    backend.draw_frame(f, had, out.stats);
    fb.swap();
    ++out.stats.frames;
    driver.frame_ended([&] { return shown_image(fb); });
    driver.progress(i, i + 1, n_frames, "frames");
  }
  out.stats.had = had.counts();
  backend.finish(out.stats);
  out.stats.wall_s = driver.wall_s();
  out.shown = shown_image(fb);
  out.z = fb.z_plane();
  if (dda_tap) backend.tap_dda({});  // the tap dies with the driver
  driver.finish(out);
  return out;
}

}  // namespace girtd
