// The front end of §2, in this project's order: lighting -> view transform ->
// depth clip -> projection -> triangulator -> selection & window clip ->
// depth sort, with object and back-face culling in front of lighting. World
// polygons of one frame in, screen triangles out (farthest first). Keeps the sort order between
// frames (frame-to-frame coherence), so one FrontEnd runs one animation.
// The stages themselves are in front_end_stages.hpp (the timed pipeline runs
// them one module each); this runs them back to back.
#pragma once

#include <functional>
#include <vector>

#include "common/types.hpp"
#include "frontend/front_end_stages.hpp"

namespace girtd {

class FrontEnd {
 public:
  // `depth_max`: P of the Zp map (config depth.max_mapped).
  FrontEnd(ScreenMap screen, double depth_max, FrontEndOptions options = {}) : stages_(screen, depth_max, options) {}

  // `q`: the frame's AA width (object culling's margin). The frame's
  // triangles, farthest first, with their interior edges marked.
  std::vector<Triangle> run_frame(const WorldFrame& frame, const Window& window, double q = 1.0) {
    return run(frame, window, q, nullptr);
  }
  // The same, and the frame's polygons released once the stages are through
  // with them, before the depth sort needs its memory.
  std::vector<Triangle> run_frame_releasing(WorldFrame& frame, const Window& window, double q = 1.0) {
    return run(frame, window, q, &frame);
  }
  FrontendCounts counts() const { return stages_.counts(); }
  // Called now and then during run_frame with the frame's polygons done and
  // their total (a progress line).
  void on_progress(std::function<void(size_t done, size_t total)> report) { report_ = std::move(report); }

 private:
  std::vector<Triangle> run(const WorldFrame& frame, const Window& window, double q, WorldFrame* release);
  FrontEndStages stages_;
  std::function<void(size_t, size_t)> report_;
};

}  // namespace girtd
