#include "frontend/front_end.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/triangle_setup.hpp"
#include "frontend/depth_clip.hpp"
#include "frontend/polygon_shape.hpp"
#include "frontend/triangulator.hpp"
#include "frontend/vertex_lighting.hpp"
#include "frontend/vertex_normals.hpp"
#include "frontend/view_transform.hpp"

namespace girtd {
namespace {

struct ClippedPolygon {
  size_t source;  // index in the frame's polygon list
  std::vector<CameraVertex> v;
};

bool is_back_face(const WorldPolygon& poly, const Vec3& eye) {
  Vec3 centroid;
  for (const Vec3& p : poly.p) centroid = centroid + p;
  centroid = centroid * (1.0 / static_cast<double>(poly.p.size()));
  return dot(newell_normal(poly.p), centroid - eye) >= 0;
}

// The polygon in 2D coordinates of its own Newell plane (counter-clockwise
// about the normal). `planar` reports whether it lies in that plane.
std::vector<Point2> plane_coordinates(const std::vector<CameraVertex>& v, bool& planar) {
  std::vector<Vec3> s;
  for (const CameraVertex& c : v) s.push_back(c.s);
  const Vec3 n = normalized(newell_normal(s));
  // u: any unit vector in the plane, from the axis least aligned with n.
  const Vec3 axis = std::fabs(n.x) <= std::fabs(n.y) && std::fabs(n.x) <= std::fabs(n.z) ? Vec3{1, 0, 0}
                    : std::fabs(n.y) <= std::fabs(n.z)                                    ? Vec3{0, 1, 0}
                                                                                          : Vec3{0, 0, 1};
  const Vec3 u = normalized(cross(n, axis));
  const Vec3 w = cross(n, u);
  Vec3 centroid;
  for (const Vec3& p : s) centroid = centroid + p;
  centroid = centroid * (1.0 / static_cast<double>(s.size()));
  double radius = 0, off_plane = 0;
  std::vector<Point2> out;
  for (const Vec3& p : s) {
    const Vec3 d = p - centroid;
    radius = std::max(radius, length(d));
    off_plane = std::max(off_plane, std::fabs(dot(d, n)));
    out.push_back({dot(d, u), dot(d, w)});
  }
  planar = off_plane <= kNonPlanarTolerance * radius;
  return out;
}

}  // namespace

std::vector<FrontTriangle> FrontEnd::run_frame(const WorldFrame& frame, const Window& window) {
  const Camera& cam = frame.camera;
  const double c = frame.focal_distance;
  const std::vector<std::vector<Vec3>> normals = vertex_normals(frame.polygons);

  // Lighting, view transform and depth clip, polygon by polygon; the depth
  // extremes need the whole frame before anything is projected.
  std::vector<ClippedPolygon> clipped;
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
  bool created_any = false;
  for (size_t i = 0; i < frame.polygons.size(); ++i) {
    const WorldPolygon& poly = frame.polygons[i];
    ++counts_.polygons;
    if (has_no_area(poly.p)) {  // decided in world space, before culling: no area has no facing
      ++counts_.degenerate_polygons;
      continue;
    }
    if (frame.cull_back_faces && is_back_face(poly, cam.centre)) {
      ++counts_.culled;
      continue;
    }
    const Surface& surface = frame.surfaces.at(static_cast<size_t>(poly.surface));
    std::vector<CameraVertex> cv;
    for (size_t k = 0; k < poly.p.size(); ++k) {
      const LitVertex lit = light_vertex(surface, frame.lights, normals[i][k], normalized(cam.centre - poly.p[k]));
      cv.push_back({to_camera_space(cam, poly.p[k]), lit.r, lit.g, lit.b, lit.t, false});
    }
    std::vector<CameraVertex> kept = depth_clip(cv, c);
    if (kept.empty()) {
      ++counts_.clipped_away;
      continue;
    }
    if (std::any_of(cv.begin(), cv.end(), [&](const CameraVertex& v) { return v.s.z <= c; })) ++counts_.clipped;
    for (const CameraVertex& v : kept) {
      if (v.created) {
        created_any = true;
        continue;
      }
      zmin = std::min(zmin, v.s.z);
      zmax = std::max(zmax, v.s.z);
    }
    clipped.push_back({i, std::move(kept)});
  }
  // Vertices made at Zs = C join the depth range (Zmin = C): every Zp stays
  // exact and in 0..P, at the price of depth resolution in that frame.
  if (created_any) {
    zmin = std::min(zmin, c);
    zmax = std::max(zmax, c);
  }
  const DepthMap depth(zmin, zmax, depth_max_);

  std::vector<FrontTriangle> out;
  std::vector<SortItem> order;
  for (const ClippedPolygon& cp : clipped) {
    // The clip may make a corner twice (a vertex on Zs = C) or a sliver
    // with no area left: the same tests as for the input.
    std::vector<CameraVertex> v = cp.v;
    drop_repeated_corners(v, [](const CameraVertex& a, const CameraVertex& b) {
      return a.s.x == b.s.x && a.s.y == b.s.y && a.s.z == b.s.z;
    });
    std::vector<Vec3> s;
    for (const CameraVertex& x : v) s.push_back(x.s);
    if (has_no_area(s)) {
      ++counts_.degenerate_polygons;
      continue;
    }
    bool planar = true;
    const Triangulation tr = triangulate(plane_coordinates(v, planar));
    if (!planar && v.size() > 3) ++counts_.non_planar;
    if (tr.concave_vertices > 0) ++counts_.concave;
    if (tr.method == TriangulationMethod::kEarClipping) ++counts_.ear_clipped;
    if (tr.method == TriangulationMethod::kFallbackFan) ++counts_.triangulation_fallbacks;

    std::vector<Vertex> screen;
    for (const CameraVertex& x : v) {
      const PlanePoint p = project(x.s, cam.d_over_s);
      screen.push_back({screen_.x(p.xp), screen_.y(p.yp), depth.zp(x.s.z), x.r, x.g, x.b, x.t});
    }
    for (size_t k = 0; k < tr.triangles.size(); ++k) {
      const TriangleIndices& ti = tr.triangles[k];
      ++counts_.triangles_made;
      FrontTriangle ft;
      ft.tri.source_line = frame.polygons[cp.source].source_line;
      for (int e = 0; e < 3; ++e) {
        ft.tri.v[e] = screen[static_cast<size_t>(ti.v[e])];
        ft.made_edge[e] = ti.made_edge[e];
        if (ti.made_edge[e]) ++counts_.made_edges;
      }
      const std::optional<TriangleSetup> setup = setup_triangle(ft.tri);
      if (!setup) {
        ++counts_.degenerate_triangles;
        continue;
      }
      if (!select_start_point(*setup, window)) {
        ++counts_.discarded_off_window;
        continue;
      }
      const double key = std::max({ft.tri.v[0].z, ft.tri.v[1].z, ft.tri.v[2].z});
      order.push_back({(static_cast<uint64_t>(cp.source) << 32) | k, key, static_cast<int>(out.size())});
      out.push_back(ft);
    }
  }
  sorter_.sort(order);
  std::vector<FrontTriangle> sorted;
  sorted.reserve(out.size());
  for (const SortItem& s : order) sorted.push_back(out[static_cast<size_t>(s.index)]);
  counts_.triangles_out += sorted.size();
  return sorted;
}

FrontendCounts FrontEnd::counts() const {
  FrontendCounts c = counts_;
  c.depth_sort_comparisons = sorter_.comparisons();
  c.full_sorts = sorter_.full_sorts();
  return c;
}

}  // namespace girtd
