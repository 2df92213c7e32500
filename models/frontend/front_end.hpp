// The front end of §2, in this project's order: lighting -> view transform ->
// depth clip -> projection -> triangulator -> selection & window clip ->
// depth sort. World polygons of one frame in, screen triangles out (farthest
// first), with back-face culling as an option. Keeps the sort order between
// frames (frame-to-frame coherence), so one FrontEnd runs one animation.
#pragma once

#include <array>
#include <vector>

#include "common/types.hpp"
#include "frontend/depth_sort.hpp"
#include "frontend/frontend_counts.hpp"
#include "frontend/projection.hpp"
#include "frontend/world_frame.hpp"

namespace girtd {

struct FrontTriangle {
  Triangle tri;
  std::array<bool, 3> made_edge{};  // edge v[i] -> v[(i+1)%3] made by the triangulator
};

class FrontEnd {
 public:
  // `depth_max`: P of the Zp map (config depth.max_mapped).
  FrontEnd(ScreenMap screen, double depth_max) : screen_(screen), depth_max_(depth_max) {}

  std::vector<FrontTriangle> run_frame(const WorldFrame& frame, const Window& window);
  FrontendCounts counts() const;

 private:
  ScreenMap screen_;
  double depth_max_;
  FrontendCounts counts_;
  DepthSorter sorter_;
};

// A polygon is non-planar when a vertex lies off the Newell plane through the
// centroid by more than this fraction of the polygon's radius.
inline constexpr double kNonPlanarTolerance = 1e-3;

}  // namespace girtd
