// GIRTD's frame against Mesa llvmpipe's on the same opaque, Q = 0 screen
// triangles: coverage, colour within 1 LSB, and what the pixels that
// disagree are — an edge through the pixel's sample point (the two
// rasterizers' edge tests differ by their sub-pixel precisions) or a depth
// tie (GIRTD keeps 16 bits of Z, GL 24) — worked out in double precision
// from the triangles themselves.
#pragma once

#include <cstdint>
#include <vector>

#include "accuracy/llvmpipe_render.hpp"
#include "common/types.hpp"
#include "io/image_compare.hpp"

namespace girtd {

// A sample point this close to a triangle's edge (px) counts as on it.
inline constexpr double kEdgeTiePx = 1.0 / 64;
// Two triangles this close in depth (depth units) at a point tie.
inline constexpr double kDepthTieUnits = 2.0;

struct LlvmpipeComparison {
  ImageError image;
  DepthError depth;
  uint64_t colour_over_1lsb = 0;  // of the pixels both cover
  // The pixels that disagree (coverage, or colour by more than 1 LSB):
  uint64_t edge_ties = 0, depth_ties = 0, unexplained = 0;
  double coverage_diff_fraction() const {
    return depth.covered_a ? double(depth.coverage_diff) / double(depth.covered_a) : 0;
  }
  double colour_within_1lsb_fraction() const {
    return depth.covered_both ? 1.0 - double(colour_over_1lsb) / double(depth.covered_both) : 1;
  }
};

// a: GIRTD's frame, b: llvmpipe's, both cleared to z_clear.
LlvmpipeComparison compare_with_llvmpipe(const std::vector<Triangle>& triangles, const RgbImage& a_rgb,
                                         const std::vector<uint16_t>& a_z, const LlvmpipeFrame& b, uint16_t z_clear);

}  // namespace girtd
