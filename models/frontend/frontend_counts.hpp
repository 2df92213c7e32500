// What the front end counted, summed over the frames of a run
// (report.json `frontend`; keys declared in sim/report/report_keys.cpp).
#pragma once

#include <cstdint>

namespace girtd {

struct FrontendCounts {
  uint64_t polygons = 0;                 // polygons entering the front end
  uint64_t culled = 0;                   // back faces removed (culling on)
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
    culled += o.culled;
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
