#include "backends/render_session.hpp"

#include <optional>
#include <stdexcept>

#include "backends/dump_tap.hpp"
#include "backends/frame_driver.hpp"
#include "backends/front_end_runner.hpp"

namespace girtd {

BackendRequest backend_request(const RenderOptions& opt) { return {opt.wave.has_value(), opt.sample_timing}; }

RenderOutput render_frames(const BackendEntry& entry, FrameSource& input, const Params& params, const RenderOptions& opt) {
  if (entry.timed()) throw std::logic_error("a timed back end runs in the pipeline: " + entry.name);
  // Made before the run starts: its video memory exists before the first frame, as the hardware's does.
  const std::unique_ptr<Backend> made = entry.make(params, backend_request(opt));
  Backend& backend = *made;
  backend.prune(opt.prune);
  backend.begin(input);
  // --dump: the input as it came, the front end's triangles as drawn, or the
  // DDA parameter sets as the back end draws them.
  FrameDriver driver(entry.name, input, params, opt);
  DumpTap* tap = driver.tap();
  const bool dda_tap = tap && tap->level() == TraceLevel::kDda;
  if (dda_tap && !backend.tap_dda([tap](const DdaParams& d) { tap->write(d); }))
    // run_render refuses --dump dda up front for a back end without kDrawsWithDda.
    throw std::logic_error("--dump dda reached the " + entry.name + " back end, which has no DDA");
  const bool polygons = input.level() == TraceLevel::kPolygon;
  std::optional<FrontEndRunner> front_end;
  if (polygons) front_end.emplace(params, opt.prune);
  const size_t n_frames = input.frames();
  if (front_end && n_frames == 1 && opt.progress) front_end->show_progress();

  driver.start();
  RenderOutput out;
  for (size_t i = 0; i < n_frames; ++i) {
    TraceFrame f = driver.untimed([&] { return input.take(i); });  // a scene's frame is placed now
    if (dda_tap) tap->begin_frame(f.settings);  // its sets as the back end draws them
    if (tap && tap->level() == TraceLevel::kPolygon) tap->frame(f);  // the input, before the front end
    if (front_end) {
      // The polygons go as soon as the front end is through with them (a
      // polygon-level dump has written them already). Not the back end's:
      // wall_s leaves it out (report.json).
      f.triangles = driver.untimed([&] { return front_end->run_releasing(f.world, f.settings); });
      f.world = WorldFrame{};
    }
    if (tap && tap->level() == TraceLevel::kTriangle) tap->frame(f);  // the triangles as drawn
    backend.begin_frame(f.settings);
    for (size_t k = 0; k < f.triangles.size(); ++k) {
      backend.draw(f.triangles[k]);
      if (n_frames == 1 && (k & 0xffff) == 0xffff) driver.progress(i, k + 1, f.triangles.size(), "triangles");
    }
    for (const DdaParams& d : f.dda) backend.draw(d);
    backend.end_frame();
    ++out.stats.frames;
    driver.frame_ended([&] { return backend.shown(); });
    if (driver.failure()) {  // a picture could not be written: nothing else is
      out.problem = driver.failure();
      return out;
    }
    driver.progress(i, i + 1, n_frames, "frames");
  }
  backend.finish(out.stats);
  if (front_end) out.stats.frontend = front_end->counts();
  out.stats.wall_s = driver.wall_s();
  out.shown = backend.shown();
  out.z = backend.z_plane();
  if (dda_tap) backend.tap_dda({});  // the tap dies with the driver
  driver.finish(out);
  return out;
}

}  // namespace girtd
