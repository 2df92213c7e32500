// When a polygon is drawable, decided the same way wherever it is asked:
// repeated corners (consecutive equal corners, the last and the first
// included) count once, and a polygon without area is degenerate. Used by the
// model importer (on index lists), by the front end on its input (world
// space, before culling) and after the depth clip (camera space).
#pragma once

#include <cstddef>
#include <vector>

#include "frontend/vec3.hpp"

namespace girtd {

// A polygon has no area when |twice its vector area| <= this x perimeter^2:
// relative, so the test does not depend on the model's units; far below any
// sliver that covers a pixel (a triangle 1000 pixels long would be 1e-9
// pixels wide), far above rounding (1e-16).
inline constexpr double kZeroAreaTolerance = 1e-12;

// Removes repeated corners in place; `same(a, b)` says two corners are one.
template <typename T, typename Same>
void drop_repeated_corners(std::vector<T>& corners, Same same) {
  size_t kept = 0;
  for (size_t i = 0; i < corners.size(); ++i)
    if (kept == 0 || !same(corners[i], corners[kept - 1])) corners[kept++] = corners[i];
  while (kept > 1 && same(corners[0], corners[kept - 1])) --kept;
  corners.erase(corners.begin() + static_cast<std::ptrdiff_t>(kept), corners.end());
}

// Twice the vector area (the Newell normal), summed as a fan from the first
// corner so that rounding does not grow with the distance from the origin.
// `at(i)` is corner i of n.
template <typename At>
Vec3 twice_vector_area(size_t n, At at) {
  Vec3 v;
  for (size_t i = 1; i + 1 < n; ++i) v = v + cross(at(i) - at(0), at(i + 1) - at(0));
  return v;
}
inline Vec3 twice_vector_area(const std::vector<Vec3>& p) {
  return twice_vector_area(p.size(), [&](size_t i) -> const Vec3& { return p[i]; });
}

// Fewer than 3 corners, or no area by kZeroAreaTolerance.
template <typename At>
bool has_no_area(size_t n, At at) {
  if (n < 3) return true;
  double perimeter = 0;
  for (size_t i = 0; i < n; ++i) perimeter += length(at((i + 1) % n) - at(i));
  return length(twice_vector_area(n, at)) <= kZeroAreaTolerance * perimeter * perimeter;
}
inline bool has_no_area(const std::vector<Vec3>& p) {
  return has_no_area(p.size(), [&](size_t i) -> const Vec3& { return p[i]; });
}

}  // namespace girtd
