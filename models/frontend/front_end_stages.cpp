#include "frontend/front_end_stages.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/triangle_setup.hpp"
#include "frontend/depth_clip.hpp"
#include "frontend/interior_edges.hpp"
#include "frontend/polygon_shape.hpp"
#include "frontend/vertex_lighting.hpp"
#include "frontend/vertex_normals.hpp"
#include "frontend/view_transform.hpp"

namespace girtd {
namespace {

bool is_back_face(const WorldPolygon& poly, const Vec3& eye) {
  Vec3 centroid;
  for (const Vec3& p : poly.p) centroid = centroid + p;
  centroid = centroid * (1.0 / static_cast<double>(poly.p.size()));
  return dot(newell_normal(poly.p), centroid - eye) >= 0;
}

// The polygon in 2D coordinates of its own Newell plane (counter-clockwise
// about the normal), into `out`. `planar` reports whether it lies in that plane.
void plane_coordinates(const std::vector<CameraVertex>& v, bool& planar, std::vector<Point2>& out) {
  const Vec3 n = normalized(newell_sum(v.size(), [&](size_t i) -> const Vec3& { return v[i].s; }));
  // u: any unit vector in the plane, from the axis least aligned with n.
  const Vec3 axis = std::fabs(n.x) <= std::fabs(n.y) && std::fabs(n.x) <= std::fabs(n.z) ? Vec3{1, 0, 0}
                    : std::fabs(n.y) <= std::fabs(n.z)                                    ? Vec3{0, 1, 0}
                                                                                          : Vec3{0, 0, 1};
  const Vec3 u = normalized(cross(n, axis));
  const Vec3 w = cross(n, u);
  Vec3 centroid;
  for (const CameraVertex& c : v) centroid = centroid + c.s;
  centroid = centroid * (1.0 / static_cast<double>(v.size()));
  double radius = 0, off_plane = 0;
  out.clear();
  for (const CameraVertex& c : v) {
    const Vec3 d = c.s - centroid;
    radius = std::max(radius, length(d));
    off_plane = std::max(off_plane, std::fabs(dot(d, n)));
    out.push_back({dot(d, u), dot(d, w)});
  }
  planar = off_plane <= kNonPlanarTolerance * radius;
}

// The polygon's corners (camera space) have no area.
bool no_area(const std::vector<CameraVertex>& v) {
  return has_no_area(v.size(), [&](size_t i) -> const Vec3& { return v[i].s; });
}

}  // namespace

void FrontEndStages::begin_frame(const WorldFrame& frame, const Window& window, double q) {
  frame_ = &frame;
  window_ = window;
  depth_range_margin_px_ = culling_margin_px(q) - 0.5;
  if (options_.cull_objects || options_.prune_lighting_out_of_view)
    view_volume_ = ViewVolume(frame.camera, frame.focal_distance, screen_, window, culling_margin_px(q));
  normals_ = {};  // made by the first light() of the frame (only the lighting stage needs them)
  zmin_ = std::numeric_limits<double>::infinity();
  zmax_ = -zmin_;
  created_any_ = false;
}

bool FrontEndStages::keep_object(const WorldObject& object) {
  counts_.polygons += object.count;
  ++counts_.objects;
  if (!options_.cull_objects || !view_volume_.misses(bounding_sphere(frame_->polygons, object))) return true;
  ++counts_.objects_culled;
  counts_.object_culled_polygons += object.count;
  for (size_t i = object.first; i < object.first + object.count; ++i) {
    counts_.object_culled_corners += frame_->polygons[i].p.size();
    counts_.object_culled_corner_lights += frame_->polygons[i].p.size() * frame_->lights.directional.size();
  }
  return false;
}

bool FrontEndStages::keep_polygon(size_t i) {
  const WorldFrame& frame = *frame_;
  const WorldPolygon& poly = frame.polygons[i];
  // No area has no facing: such a polygon goes on, and lighting drops it.
  if (!back_face_test_on() || has_no_area(poly.p) || !is_back_face(poly, frame.camera.centre)) return true;
  const Surface& surface = frame.surfaces.at(static_cast<size_t>(poly.surface));
  if (!frame.cull_back_faces && (surface.t_min > 0 || surface.t_max > 0)) {
    // Forced by the config, not asked for by the input: a transparent
    // surface's back faces show through its front, so they stay.
    ++counts_.back_faces_exempt;
    counts_.exempt_surfaces.insert(poly.surface);
    return true;
  }
  ++counts_.culled;
  counts_.culled_corners += poly.p.size();
  counts_.culled_corner_lights += poly.p.size() * frame.lights.directional.size();
  return false;
}

bool FrontEndStages::light(size_t i, FrontPolygon& out) {
  const WorldFrame& frame = *frame_;
  const WorldPolygon& poly = frame.polygons[i];
  if (has_no_area(poly.p)) {  // decided in world space; keep_polygon passed it on: no area has no facing
    ++counts_.degenerate_polygons;
    return false;
  }
  const Camera& cam = frame.camera;
  out.source = i;
  out.v.clear();
  if (options_.prune_lighting_out_of_view && view_volume_.misses(poly.p)) {
    for (const Vec3& p : poly.p) out.v.push_back({p, 0, 0, 0, 1, false});  // its colours are never drawn
    ++counts_.unlit;
    return true;
  }
  if (normals_.empty()) normals_ = vertex_normals(frame.polygons);
  const Surface& surface = frame.surfaces.at(static_cast<size_t>(poly.surface));
  Surface corner = surface;  // the surface with a corner's own diffuse colour
  for (size_t k = 0; k < poly.p.size(); ++k) {
    if (!poly.colour.empty()) corner.r = poly.colour[k].r, corner.g = poly.colour[k].g, corner.b = poly.colour[k].b;
    const LitVertex lit = light_vertex(corner, frame.lights, normals_.at(i, k), normalized(cam.centre - poly.p[k]));
    out.v.push_back({poly.p[k], lit.r, lit.g, lit.b, lit.t, false});
  }
  return true;
}

std::optional<FrontPolygon> FrontEndStages::light(size_t i) {
  FrontPolygon out;
  if (!light(i, out)) return std::nullopt;
  return out;
}

void FrontEndStages::view(FrontPolygon& p) const {
  for (CameraVertex& v : p.v) v.s = to_camera_space(frame_->camera, v.s);
}

bool FrontEndStages::depth_clip(const FrontPolygon& p, FrontPolygon& out) {
  const double c = frame_->focal_distance;
  out.source = p.source;
  girtd::depth_clip(p.v, c, out.v);
  if (out.v.empty()) {
    ++counts_.clipped_away;
    return false;
  }
  if (std::any_of(p.v.begin(), p.v.end(), [&](const CameraVertex& v) { return v.s.z <= c; })) ++counts_.clipped;
  return true;
}

std::optional<FrontPolygon> FrontEndStages::depth_clip(const FrontPolygon& p) {
  FrontPolygon out;
  if (!depth_clip(p, out)) return std::nullopt;
  return out;
}

void FrontEndStages::note_depths(const FrontPolygon& p) {
  // Only polygons that can reach the window set the depth range: geometry
  // beside the window wastes no Z resolution, and object culling (whose
  // margin is half a pixel wider) leaves every Zp as it was.
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const CameraVertex& v : p.v) {
    const PlanePoint pp = girtd::project(v.s, frame_->camera.d_over_s);
    x0 = std::min(x0, screen_.x(pp.xp));
    x1 = std::max(x1, screen_.x(pp.xp));
    y0 = std::min(y0, screen_.y(pp.yp));
    y1 = std::max(y1, screen_.y(pp.yp));
  }
  const double m = depth_range_margin_px_;
  if (x1 < window_.x0 - m || x0 > window_.x1 + m || y1 < window_.y0 - m || y0 > window_.y1 + m) return;
  for (const CameraVertex& v : p.v) {
    if (v.created) {
      created_any_ = true;
      continue;
    }
    zmin_ = std::min(zmin_, v.s.z);
    zmax_ = std::max(zmax_, v.s.z);
  }
}

DepthMap FrontEndStages::depth_map() const {
  // Vertices made at Zs = C join the depth range (Zmin = C): every Zp stays
  // exact and in 0..P, at the price of depth resolution in that frame.
  double zmin = zmin_, zmax = zmax_;
  if (created_any_) {
    const double c = frame_->focal_distance;
    zmin = std::min(zmin, c);
    zmax = std::max(zmax, c);
  }
  return DepthMap(zmin, zmax, depth_max_);
}

bool FrontEndStages::project(const FrontPolygon& p, ScreenPolygon& out) {
  // The clip may make a corner twice (a vertex on Zs = C) or a sliver with
  // no area left: the same tests as for the input.
  out.source = p.source;
  out.v = p.v;
  drop_repeated_corners(out.v, [](const CameraVertex& a, const CameraVertex& b) {
    return a.s.x == b.s.x && a.s.y == b.s.y && a.s.z == b.s.z;
  });
  if (no_area(out.v)) {
    ++counts_.degenerate_polygons;
    return false;
  }
  out.screen.clear();
  for (const CameraVertex& x : out.v) {
    const PlanePoint pp = girtd::project(x.s, frame_->camera.d_over_s);
    out.screen.push_back({screen_.x(pp.xp), screen_.y(pp.yp), x.s.z, x.r, x.g, x.b, x.t});
  }
  return true;
}

std::optional<ScreenPolygon> FrontEndStages::project(const FrontPolygon& p, const DepthMap& depth) {
  ScreenPolygon out;
  if (!project(p, out)) return std::nullopt;
  for (Vertex& v : out.screen) v.z = depth.zp(v.z);
  return out;
}

void FrontEndStages::triangulate(const ScreenPolygon& p, Triangulated& out) {
  bool planar = true;
  plane_coordinates(p.v, planar, plane_);
  girtd::triangulate(plane_, triangulation_);
  const Triangulation& tr = triangulation_;
  if (!planar && p.v.size() > 3) ++counts_.non_planar;
  if (tr.concave_vertices > 0) ++counts_.concave;
  if (tr.method == TriangulationMethod::kEarClipping) ++counts_.ear_clipped;
  if (tr.method == TriangulationMethod::kFallbackFan) ++counts_.triangulation_fallbacks;
  out.triangles.clear();
  out.method = tr.method;
  out.corners = p.v.size();
  for (size_t k = 0; k < tr.triangles.size(); ++k) {
    const TriangleIndices& ti = tr.triangles[k];
    ++counts_.triangles_made;
    SortableTriangle st;
    st.id = (static_cast<uint64_t>(p.source) << 32) | k;
    st.ft.tri.source_line = frame_->polygons[p.source].source_line;
    st.ft.tri.surface = frame_->polygons[p.source].surface;
    for (int e = 0; e < 3; ++e) {
      st.ft.tri.v[e] = p.screen[static_cast<size_t>(ti.v[e])];
      st.ft.made_edge[e] = ti.made_edge[e];
      if (ti.made_edge[e]) ++counts_.made_edges;
    }
    out.triangles.push_back(st);
  }
}

Triangulated FrontEndStages::triangulate(const ScreenPolygon& p) {
  Triangulated out;
  triangulate(p, out);
  return out;
}

bool FrontEndStages::window_select(const SortableTriangle& t) {
  const std::optional<TriangleSetup> setup = setup_triangle(t.ft.tri);
  if (!setup) {
    ++counts_.degenerate_triangles;
    return false;
  }
  if (!select_start_point(*setup, window_)) {
    ++counts_.discarded_off_window;
    return false;
  }
  return true;
}

void FrontEndStages::sort(std::vector<Triangle>& triangles, const std::vector<uint64_t>& ids) {
  sort_in_place(triangles, ids);
  mark_interior_edges(triangles);  // after the sort's own memory has gone
  counts_.triangles_out += triangles.size();
}

void FrontEndStages::sort_in_place(std::vector<Triangle>& triangles, const std::vector<uint64_t>& ids) {
  std::vector<SortItem> order;
  order.reserve(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& t = triangles[i];
    order.push_back({ids[i], std::max({t.v[0].z, t.v[1].z, t.v[2].z}), static_cast<uint32_t>(i)});
  }
  sorter_.sort(order);
  // Triangle k of the sorted frame is triangles[order[k].index]: each cycle
  // of that permutation is walked once, so no second frame is held.
  std::vector<bool> placed(triangles.size(), false);
  for (size_t k = 0; k < triangles.size(); ++k) {
    if (placed[k]) continue;
    const Triangle first = triangles[k];
    size_t at = k;
    while (true) {
      placed[at] = true;
      const size_t from = order[at].index;
      if (from == k) {
        triangles[at] = first;
        break;
      }
      triangles[at] = triangles[from];
      at = from;
    }
  }
}

FrontendCounts FrontEndStages::counts() const {
  FrontendCounts c = counts_;
  c.depth_sort_comparisons = sorter_.comparisons();
  c.full_sorts = sorter_.full_sorts();
  return c;
}

}  // namespace girtd
