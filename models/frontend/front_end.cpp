#include "frontend/front_end.hpp"

namespace girtd {

std::vector<Triangle> FrontEnd::run(const WorldFrame& frame, const Window& window, double q, WorldFrame* release) {
  FrontEndStages& s = stages_;
  s.begin_frame(frame, window, q);
  // A polygon's way through the stages, in storage reused for the next one.
  FrontPolygon lit, clipped;
  ScreenPolygon screen;
  Triangulated made;
  std::vector<Triangle> out;
  std::vector<uint64_t> ids;
  size_t expected = 0;  // a fan's n - 2 triangles per polygon
  for (const WorldPolygon& p : frame.polygons) expected += p.p.size() > 2 ? p.p.size() - 2 : 0;
  out.reserve(expected);
  ids.reserve(expected);
  // Projection needs the frame's depth range (every clipped polygon's depths)
  // for Zp. The polygons go on with Zs as z, and each triangle's z becomes
  // Zp once the range is known: window selection looks at x and y only, and
  // the same Zs maps to the same Zp now as after a frame-long hold.
  for (const WorldObject& object : frame_objects(frame)) {
    if (!s.keep_object(object)) continue;
    for (size_t i = object.first; i < object.first + object.count; ++i) {
      if (report_ && (i & 0x3fff) == 0) report_(i, frame.polygons.size());
      if (!s.keep_polygon(i) || !s.light(i, lit)) continue;
      s.view(lit);
      if (!s.depth_clip(lit, clipped)) continue;
      s.note_depths(clipped);
      if (!s.project(clipped, screen)) continue;
      s.triangulate(screen, made);
      for (const SortableTriangle& t : made.triangles)
        if (s.window_select(t)) {
          out.push_back(t.ft.tri);
          ids.push_back(t.id);
        }
    }
  }
  if (report_) report_(frame.polygons.size(), frame.polygons.size());
  s.lighting_done();
  if (release) std::vector<WorldPolygon>().swap(release->polygons);
  const DepthMap depth = s.depth_map();
  for (Triangle& t : out) FrontEndStages::map_depth(t, depth);
  s.sort(out, ids);
  return out;
}

}  // namespace girtd
