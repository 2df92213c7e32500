// Random screen-space triangles for property tests, regressions and claims:
// log-uniform size (0.5 px .. max_size) anywhere on the screen, random
// colours and depth, some translucent.
#pragma once

#include <random>

#include "common/types.hpp"

namespace girtd {

Triangle random_triangle(std::mt19937& rng, double max_size);

}  // namespace girtd

namespace girtd {

// An opaque triangle of `area` pixels (random shape, no slivers: its
// smallest angle is at least 15 degrees), wholly inside a width x height
// screen, its vertices on a 1/256-px grid (which llvmpipe, with 8 sub-pixel
// bits, represents exactly); random colours and depth. The llvmpipe comparison's and the speed
// bench's workload.
Triangle random_opaque_triangle(std::mt19937& rng, double area, int width, int height);

}  // namespace girtd
