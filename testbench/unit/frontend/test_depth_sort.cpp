// Depth sort: a full sort first, then frame-to-frame coherence.
#include <catch2/catch.hpp>

#include "frontend/depth_sort.hpp"

using namespace girtd;

namespace {

std::vector<SortItem> items(std::initializer_list<double> keys) {
  std::vector<SortItem> v;
  uint64_t id = 0;
  for (double k : keys) v.push_back({id++, k, 0});
  return v;
}

}  // namespace

TEST_CASE("depth sort: farthest first; an unchanged frame costs n - 1 comparisons", "[frontend]") {
  DepthSorter s;
  auto a = items({10, 50, 30, 40, 20});
  s.sort(a);
  CHECK(s.full_sorts() == 1);
  CHECK(a[0].key == 50);
  CHECK(a[4].key == 10);
  const uint64_t first = s.comparisons();

  // Same five triangles, same depths, listed in another order: the previous
  // order is already sorted -> 5 - 1 = 4 comparisons, no full sort.
  auto b = items({10, 50, 30, 40, 20});
  s.sort(b);
  CHECK(s.comparisons() - first == 4);
  CHECK(s.full_sorts() == 1);
  CHECK(b[0].key == 50);

  // One triangle moves from 3rd to front (key 30 -> 60): previous order
  // 50 40 30 20 10 becomes 50 40 60 20 10; insertion: 40<50 (1), 60 vs 40 swap (2),
  // 60 vs 50 swap (3), 20 vs 40 (4), 10 vs 20 (5) -> 5 comparisons.
  const uint64_t before = s.comparisons();
  auto c = items({10, 50, 60, 40, 20});
  s.sort(c);
  CHECK(s.comparisons() - before == 5);
  CHECK(c[0].key == 60);
  CHECK(c[1].key == 50);
}
