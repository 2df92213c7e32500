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

TEST_CASE("depth sort: farthest first, an unchanged frame costs n - 1 comparisons", "[frontend]") {
  DepthSorter s;
  auto a = items({10, 50, 30, 40, 20});
  s.sort(a);
  CHECK(s.full_sorts() == 1);
  CHECK(a[0].key == 50);
  CHECK(a[4].key == 10);
  const uint64_t first = s.comparisons();

  // Same five triangles, same depths, listed in another order (ids 3 0 4 1 2):
  // matched by id, the previous order is already sorted -> 5 - 1 = 4
  // comparisons, no full sort.
  std::vector<SortItem> b = {{3, 40, 0}, {0, 10, 1}, {4, 20, 2}, {1, 50, 3}, {2, 30, 4}};
  s.sort(b);
  CHECK(s.comparisons() - first == 4);
  CHECK(s.full_sorts() == 1);
  std::vector<uint64_t> ids;
  for (const SortItem& i : b) ids.push_back(i.id);
  CHECK(ids == std::vector<uint64_t>{1, 3, 2, 4, 0});
  CHECK(b[0].index == 3);  // the payload travels with its item

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

TEST_CASE("depth sort: a frame sharing less than half its triangles is sorted afresh", "[frontend]") {
  DepthSorter s;
  std::vector<SortItem> a = {{0, 1, 0}, {1, 2, 1}, {2, 3, 2}, {3, 4, 3}};
  s.sort(a);
  CHECK(s.full_sorts() == 1);
  // Half shared (ids 0, 1 of 4): coherent. The previous order 3 2 1 0 keeps
  // 1 0, the newcomers 5 6 are appended, insertion sort gives 5 6 1 0.
  std::vector<SortItem> b = {{0, 1, 0}, {1, 2, 1}, {5, 9, 2}, {6, 8, 3}};
  s.sort(b);
  CHECK(s.full_sorts() == 1);
  CHECK(b[0].id == 5);
  CHECK(b[3].id == 0);
  // One of four shared: full sort.
  std::vector<SortItem> c = {{0, 1, 0}, {7, 2, 1}, {8, 3, 2}, {9, 4, 3}};
  s.sort(c);
  CHECK(s.full_sorts() == 2);
  CHECK(c[0].id == 9);
}

TEST_CASE("depth sort: a frame that turns round stops the coherent pass and is sorted afresh", "[frontend]") {
  // n = 1000: budget n ceil(log2 n) + n = 1000 x 10 + 1000 = 11000.
  CHECK(coherent_budget(1000) == 11000);
  CHECK(coherent_budget(1) == 1);
  const uint64_t n = 1000;
  auto frame = [&](double sign) {
    std::vector<SortItem> v;
    for (uint64_t id = 0; id < n; ++id) v.push_back({id, sign * static_cast<double>(id), static_cast<int>(id)});
    return v;
  };
  DepthSorter s;
  auto a = frame(1);
  s.sort(a);
  CHECK(s.full_sorts() == 1);
  const uint64_t c1 = s.comparisons();
  // Every key negated: the previous order is exactly backwards. Insertion sort
  // would take n(n - 1)/2 = 499500 comparisons; it stops at 11000 and a stable
  // sort (at most about n log2 n = 10000 more) takes over.
  auto b = frame(-1);
  s.sort(b);
  CHECK(s.full_sorts() == 2);
  CHECK(s.comparisons() - c1 <= 11000 + 12000);
  for (uint64_t i = 0; i < n; ++i) CHECK(b[i].id == i);
  // The same frame again: n - 1 comparisons, no full sort.
  const uint64_t c2 = s.comparisons();
  auto c = frame(-1);
  s.sort(c);
  CHECK(s.comparisons() - c2 == n - 1);
  CHECK(s.full_sorts() == 2);
}
