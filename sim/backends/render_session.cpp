#include "backends/render_session.hpp"

#include <chrono>
#include <cstdio>
#include <memory>

#include "common/input_error.hpp"
#include "dda/dda_preparer.hpp"
#include "io/trace_writer.hpp"

namespace girtd {
namespace {

// Writes the stream crossing one boundary while the trace renders.
class DumpTap {
 public:
  DumpTap(const DumpRequest& req, const Trace& trace, const Params& params, const Trace* polygons)
      : level_(req.level), preparer_(params), polygons_(polygons) {
    if (trace.level == TraceLevel::kThesis)
      throw InputError(req.path, 0, "a thesis trace runs the appendix program whole: it has no stage boundary to dump");
    if (trace.level == TraceLevel::kDda && level_ == TraceLevel::kTriangle)
      throw InputError(req.path, 0, "cannot dump triangles from a DDA-level trace (the preparer's input is gone)");
    if (level_ == TraceLevel::kPolygon && !polygons_)
      throw InputError(req.path, 0, "cannot dump polygons: the input entered below the front end");
    writer_ = std::make_unique<TraceWriter>(req.path, level_, params, "dumped by girtd render from " + trace.path);
  }
  void frame(const TraceFrame& f) {
    writer_->begin_frame(f.settings);
    if (level_ == TraceLevel::kPolygon) {
      writer_->write(polygons_->frames.at(polygon_frame_++).world);
      return;
    }
    if (level_ == TraceLevel::kTriangle) {
      for (const Triangle& t : f.triangles) writer_->write(t);
      return;
    }
    for (const DdaParams& d : f.dda) writer_->write(d);
    DdaParams p;
    for (const Triangle& t : f.triangles)
      if (preparer_.prepare(t, f.settings, p) == PrepareResult::kReady) writer_->write(p);
  }
  void commit() { writer_->commit(); }

 private:
  TraceLevel level_;
  DdaPreparer preparer_;
  std::unique_ptr<TraceWriter> writer_;
  const Trace* polygons_;
  size_t polygon_frame_ = 0;
};

}  // namespace

RgbImage shown_image(const FrameBuffer& fb) {
  RgbImage img;
  img.width = fb.width();
  img.height = fb.height();
  img.rgb = fb.shown_bytes();
  return img;
}

RenderOutput render_trace(const Trace& trace, Backend& backend, const Params& params, const RenderOptions& opt) {
  backend.begin(trace);
  std::unique_ptr<DumpTap> tap;
  if (opt.dump) tap = std::make_unique<DumpTap>(*opt.dump, trace, params, opt.polygon_source);

  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  RenderOutput out;
  FrameBuffer fb(params.screen_width, params.screen_height, static_cast<uint16_t>(params.depth_clear));
  Had had(fb, params.one_minus_nf);
  // The thesis program draws a 128 x 96 picture in the frame's top-left corner.
  if (trace.level == TraceLevel::kThesis) had.set_screen(params.thesis.width, params.thesis.height);
  const size_t n_frames = trace.frames.size();
  bool printed = false;
  for (size_t i = 0; i < n_frames; ++i) {
    const TraceFrame& f = trace.frames[i];
    if (tap) tap->frame(f);
    fb.clear_back(f.settings.background);
    had.set_drop_partial(f.settings.qq);
    backend.draw_frame(f, had, out.stats);
    fb.swap();
    ++out.stats.frames;
    if (opt.keep_all_frames) out.per_frame.push_back(shown_image(fb));
    if (opt.progress && std::chrono::duration<double>(clock::now() - t0).count() > 1.0) {
      std::fprintf(stderr, "\r[girtd] %s: frame %zu/%zu", backend.name().c_str(), i + 1, n_frames);
      printed = true;
    }
  }
  if (printed) std::fprintf(stderr, "\n");
  out.stats.had = had.counts();
  backend.finish(out.stats);
  out.stats.wall_s = std::chrono::duration<double>(clock::now() - t0).count();
  out.shown = shown_image(fb);
  out.z = fb.z_plane();
  if (tap) tap->commit();
  return out;
}

}  // namespace girtd
