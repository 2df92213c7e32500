// Random screen-space triangles for property tests, regressions and claims:
// log-uniform size (0.5 px .. max_size) anywhere on the screen, random
// colours and depth, some translucent.
#pragma once

#include <random>

#include "common/types.hpp"

namespace girtd {

Triangle random_triangle(std::mt19937& rng, double max_size);

}  // namespace girtd
