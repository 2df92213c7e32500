// What the front end counted, summed over the frames of a run
// (report.json `frontend`; keys declared in sim/report/report_keys.cpp).
#pragma once

#include <cstdint>
#include <set>

namespace girtd {

struct FrontendCounts {
  uint64_t polygons = 0;                 // polygons entering the front end
  uint64_t objects = 0;                  // objects entering it (a scene's models; WorldObject)
  uint64_t objects_culled = 0;           // objects whose bounding sphere misses the view volume: removed
  uint64_t object_culled_polygons = 0;   // their polygons
  uint64_t culled = 0;                   // back faces removed (culling on)
  uint64_t back_faces_exempt = 0;        // back faces of transparent surfaces kept under culling.back_faces "always"
  std::set<int> exempt_surfaces;         // their surface ids
  // Corners, and corners x directional lights, of the polygons culling
  // removed: what the flops they would have cost are computed from.
  uint64_t object_culled_corners = 0, object_culled_corner_lights = 0;
  uint64_t culled_corners = 0, culled_corner_lights = 0;
  // Simulator, not hardware: polygons pruning left unlit (not in report.json's counts).
  uint64_t unlit = 0;
  uint64_t clipped = 0;                  // polygons cut by the depth clip (some vertex at Zs <= C)
  uint64_t clipped_away = 0;             // polygons wholly at Zs <= C: dropped
  uint64_t degenerate_polygons = 0;      // no area (polygon_shape.hpp), at input or after the clip: dropped
  uint64_t non_planar = 0;               // polygons off their Newell plane by > 1e-3 of their radius
  uint64_t concave = 0;                  // polygons with at least one concave vertex
  uint64_t ear_clipped = 0;              // polygons with two or more (ear clipping)
  uint64_t triangulation_fallbacks = 0;  // self-intersecting: fanned from vertex 0
  uint64_t triangles_made = 0;           // triangles out of the triangulator
  uint64_t made_edges = 0;               // triangulator-made (invisible in wire-frame) edges
  uint64_t degenerate_triangles = 0;     // no area on the screen: discarded
  uint64_t discarded_off_window = 0;     // no start point (§3 selection): discarded
  uint64_t triangles_out = 0;            // triangles handed to the preparer
  uint64_t depth_sort_comparisons = 0;
  uint64_t full_sorts = 0;               // frames sorted from scratch (no usable previous order)

  // Counts of stages run apart (one per pipeline module) add up.
  FrontendCounts& operator+=(const FrontendCounts& o) {
    polygons += o.polygons;
    objects += o.objects;
    objects_culled += o.objects_culled;
    object_culled_polygons += o.object_culled_polygons;
    culled += o.culled;
    back_faces_exempt += o.back_faces_exempt;
    exempt_surfaces.insert(o.exempt_surfaces.begin(), o.exempt_surfaces.end());
    object_culled_corners += o.object_culled_corners;
    object_culled_corner_lights += o.object_culled_corner_lights;
    culled_corners += o.culled_corners;
    culled_corner_lights += o.culled_corner_lights;
    unlit += o.unlit;
    clipped += o.clipped;
    clipped_away += o.clipped_away;
    degenerate_polygons += o.degenerate_polygons;
    non_planar += o.non_planar;
    concave += o.concave;
    ear_clipped += o.ear_clipped;
    triangulation_fallbacks += o.triangulation_fallbacks;
    triangles_made += o.triangles_made;
    made_edges += o.made_edges;
    degenerate_triangles += o.degenerate_triangles;
    discarded_off_window += o.discarded_off_window;
    triangles_out += o.triangles_out;
    depth_sort_comparisons += o.depth_sort_comparisons;
    full_sorts += o.full_sorts;
    return *this;
  }
};

}  // namespace girtd
