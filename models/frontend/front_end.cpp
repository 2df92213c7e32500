#include "frontend/front_end.hpp"

namespace girtd {

std::vector<FrontTriangle> FrontEnd::run_frame(const WorldFrame& frame, const Window& window, double q) {
  FrontEndStages& s = stages_;
  s.begin_frame(frame, window, q);
  // Culling, lighting, view transform and depth clip, polygon by polygon;
  // the depth extremes need the whole frame before anything is projected.
  std::vector<FrontPolygon> clipped;
  for (const WorldObject& object : frame_objects(frame)) {
    if (!s.keep_object(object)) continue;
    for (size_t i = object.first; i < object.first + object.count; ++i) {
      if (!s.keep_polygon(i)) continue;
      std::optional<FrontPolygon> p = s.light(i);
      if (!p) continue;
      s.view(*p);
      std::optional<FrontPolygon> kept = s.depth_clip(*p);
      if (!kept) continue;
      s.note_depths(*kept);
      clipped.push_back(std::move(*kept));
    }
  }
  const DepthMap depth = s.depth_map();
  std::vector<SortableTriangle> selected;
  for (const FrontPolygon& p : clipped) {
    const std::optional<ScreenPolygon> sp = s.project(p, depth);
    if (!sp) continue;
    for (const SortableTriangle& t : s.triangulate(*sp).triangles)
      if (s.window_select(t)) selected.push_back(t);
  }
  return s.sort(selected);
}

}  // namespace girtd
