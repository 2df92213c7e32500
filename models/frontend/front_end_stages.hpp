// The front end of §2 cut at its stage boundaries, so that a timed pipeline
// (sim/pipeline) can run one stage per module and FrontEnd::run_frame can
// run them back to back: both give the same triangles in the same order.
//   light -> view -> depth_clip -> [projection holds the frame: note_depths,
//   then depth_map] -> project -> triangulate -> window_select -> [depth sort
//   holds the frame: sort]
// A stage returning nullopt (or nothing) dropped the item and counted why.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/types.hpp"
#include "frontend/camera_vertex.hpp"
#include "frontend/depth_sort.hpp"
#include "frontend/frontend_counts.hpp"
#include "frontend/projection.hpp"
#include "frontend/triangulator.hpp"
#include "frontend/world_frame.hpp"

namespace girtd {

// A polygon is non-planar when a vertex lies off the Newell plane through the
// centroid by more than this fraction of the polygon's radius.
inline constexpr double kNonPlanarTolerance = 1e-3;

struct FrontTriangle {
  Triangle tri;
  std::array<bool, 3> made_edge{};  // edge v[i] -> v[(i+1)%3] made by the triangulator
};

// One polygon between lighting and projection. Each vertex's `s` is its
// world position after light() and its camera-space position after view().
struct FrontPolygon {
  size_t source = 0;  // index in the frame's polygon list
  std::vector<CameraVertex> v;
};

// A projected polygon: camera space (the triangulator works in the
// polygon's own plane) and screen vertices.
struct ScreenPolygon {
  size_t source = 0;
  std::vector<CameraVertex> v;
  std::vector<Vertex> screen;
};

// A triangle between the triangulator and the depth sort.
struct SortableTriangle {
  FrontTriangle ft;
  uint64_t id = 0;  // (polygon << 32) | triangle: the same in every frame of an animation
};

struct Triangulated {
  std::vector<SortableTriangle> triangles;  // before the screen-area test
  TriangulationMethod method = TriangulationMethod::kConvexFan;
  size_t corners = 0;
};

class FrontEndStages {
 public:
  // `depth_max`: P of the Zp map (config depth.max_mapped).
  FrontEndStages(ScreenMap screen, double depth_max) : screen_(screen), depth_max_(depth_max) {}

  // Each stage's instance is told the frame it is working on (stages run
  // apart work on different frames at once). Vertex normals are not charged
  // as work: the thesis' database stores them.
  void begin_frame(const WorldFrame& frame, const Window& window);
  const WorldFrame& frame() const { return *frame_; }

  // Lighting, with the no-area and back-face tests before it.
  std::optional<FrontPolygon> light(size_t polygon);
  void view(FrontPolygon& p) const;
  // Keeps Zs > C; nullopt when nothing is left.
  std::optional<FrontPolygon> depth_clip(const FrontPolygon& p);
  // Projection's frame-long hold: every clipped polygon's depths, then the map.
  void note_depths(const FrontPolygon& p);
  DepthMap depth_map() const;
  // Repeated corners and no-area slivers the clip made are dropped here.
  std::optional<ScreenPolygon> project(const FrontPolygon& p, const DepthMap& depth);
  Triangulated triangulate(const ScreenPolygon& p);
  // Selection and window clip (§3): false = no screen area or no start point.
  bool window_select(const SortableTriangle& t);
  // Depth sort (farthest first), coherent across frames.
  std::vector<FrontTriangle> sort(const std::vector<SortableTriangle>& frame_triangles);

  FrontendCounts counts() const;

 private:
  ScreenMap screen_;
  double depth_max_;
  const WorldFrame* frame_ = nullptr;
  Window window_{};
  std::vector<std::vector<Vec3>> normals_;
  double zmin_ = 0, zmax_ = 0;
  bool created_any_ = false;
  FrontendCounts counts_;
  DepthSorter sorter_;
};

}  // namespace girtd
