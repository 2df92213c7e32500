// The front end of §2, in this project's order: lighting -> view transform ->
// depth clip -> projection -> triangulator -> selection & window clip ->
// depth sort. World polygons of one frame in, screen triangles out (farthest
// first), with back-face culling as an option. Keeps the sort order between
// frames (frame-to-frame coherence), so one FrontEnd runs one animation.
// The stages themselves are in front_end_stages.hpp (the timed pipeline runs
// them one module each); this runs them back to back.
#pragma once

#include <vector>

#include "common/types.hpp"
#include "frontend/front_end_stages.hpp"

namespace girtd {

class FrontEnd {
 public:
  // `depth_max`: P of the Zp map (config depth.max_mapped).
  FrontEnd(ScreenMap screen, double depth_max) : stages_(screen, depth_max) {}

  std::vector<FrontTriangle> run_frame(const WorldFrame& frame, const Window& window);
  FrontendCounts counts() const { return stages_.counts(); }

 private:
  FrontEndStages stages_;
};

}  // namespace girtd
