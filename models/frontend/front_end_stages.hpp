// The front end of §2 cut at its stage boundaries, so that a timed pipeline
// (sim/pipeline) can run one stage per module and FrontEnd::run_frame can
// run them back to back: both give the same triangles in the same order.
//   cull -> light -> view -> depth_clip -> [projection holds the frame: note_depths,
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
#include "frontend/object_culling.hpp"
#include "frontend/projection.hpp"
#include "frontend/triangulator.hpp"
#include "frontend/vertex_normals.hpp"
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

// What the front end is built to leave out: the modeled hardware's culling
// (config `culling`) and the simulator's pruning (sim/backends/prune_plan).
struct FrontEndOptions {
  bool cull_objects = false;            // bounding-sphere culling of whole objects (culling.objects)
  bool cull_back_faces_always = false;  // back faces culled in every frame (culling.back_faces "always")
  // Simulator only: a polygon wholly outside the view volume is not lit
  // (the depth clip or the window clip drops all it makes; its lighting
  // flops are still charged).
  bool prune_lighting_out_of_view = false;
};

// The AA fringe's width plus a pixel for rounding: how far outside the window
// the view volume of object culling reaches, in pixels.
inline double culling_margin_px(double q) { return q + 1; }

class FrontEndStages {
 public:
  // `depth_max`: P of the Zp map (config depth.max_mapped).
  FrontEndStages(ScreenMap screen, double depth_max, FrontEndOptions options = {})
      : screen_(screen), depth_max_(depth_max), options_(options) {}

  // Each stage's instance is told the frame it is working on (stages run
  // apart work on different frames at once). Vertex normals are not charged
  // as work: the thesis' database stores them. `q`: the frame's AA width.
  void begin_frame(const WorldFrame& frame, const Window& window, double q);
  const WorldFrame& frame() const { return *frame_; }
  const FrontEndOptions& options() const { return options_; }

  // Culling, in front of lighting: whole objects by their bounding sphere
  // (when culling.objects is on; every polygon of the object counts as
  // entering the front end), then back faces polygon by polygon.
  bool keep_object(const WorldObject& object);
  bool back_face_test_on() const { return frame_->cull_back_faces || options_.cull_back_faces_always; }
  bool keep_polygon(size_t polygon);

  // Each stage comes twice: into a caller's object, whose storage is reused
  // (FrontEnd::run_frame's loop allocates nothing per polygon), and as a
  // value (the timed pipeline's items). false / nullopt: dropped.
  // Lighting, with the no-area test before it.
  bool light(size_t polygon, FrontPolygon& out);
  std::optional<FrontPolygon> light(size_t polygon);
  void view(FrontPolygon& p) const;
  // The frame's last polygon is lit: the shared normals' memory goes (the
  // depth sort and its edge marking need theirs next).
  void lighting_done() { normals_ = {}; }
  // Keeps Zs > C; false when nothing is left.
  bool depth_clip(const FrontPolygon& p, FrontPolygon& out);
  std::optional<FrontPolygon> depth_clip(const FrontPolygon& p);
  // Projection's frame-long hold: the depths of every clipped polygon whose
  // screen box meets the window (widened by the fringe), then the map.
  void note_depths(const FrontPolygon& p);
  DepthMap depth_map() const;
  // Repeated corners and no-area slivers the clip made are dropped here.
  // Without a depth map the screen vertices keep Zs as z, for map_depth once
  // the frame's range is known (the same Zs in, the same Zp out).
  bool project(const FrontPolygon& p, ScreenPolygon& out);
  std::optional<ScreenPolygon> project(const FrontPolygon& p, const DepthMap& depth);
  static void map_depth(Triangle& t, const DepthMap& depth) {
    for (Vertex& v : t.v) v.z = depth.zp(v.z);
  }
  void triangulate(const ScreenPolygon& p, Triangulated& out);
  Triangulated triangulate(const ScreenPolygon& p);
  // Selection and window clip (§3): false = no screen area or no start point.
  // Decided by x and y alone: z may still be Zs.
  bool window_select(const SortableTriangle& t);
  // Depth sort (farthest first), coherent across frames: `triangles` in
  // place (ids[i] is triangles[i]'s SortableTriangle::id), then their
  // interior edges marked.
  void sort(std::vector<Triangle>& triangles, const std::vector<uint64_t>& ids);

  FrontendCounts counts() const;

 private:
  ScreenMap screen_;
  double depth_max_;
  FrontEndOptions options_;
  const WorldFrame* frame_ = nullptr;
  ViewVolume view_volume_;
  double depth_range_margin_px_ = 0;
  Window window_{};
  VertexNormals normals_;
  double zmin_ = 0, zmax_ = 0;
  bool created_any_ = false;
  FrontendCounts counts_;
  DepthSorter sorter_;
  // Scratch reused polygon after polygon.
  std::vector<Point2> plane_;
  Triangulation triangulation_;

  void sort_in_place(std::vector<Triangle>& triangles, const std::vector<uint64_t>& ids);
};

}  // namespace girtd
