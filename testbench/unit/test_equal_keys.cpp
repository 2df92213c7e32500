// for_each_equal_key against an independent grouping (std::map), on enough
// items to take the parallel path and with a hash that collides on purpose:
// every set is found whole, once, its indices ascending, and keys that share
// a hash are never merged.
#include <catch2/catch.hpp>

#include <map>
#include <vector>

#include "common/equal_keys.hpp"

namespace {

struct CollidingKey {
  int v;
  bool operator==(const CollidingKey& o) const { return v == o.v; }
  template <class H>
  friend H AbslHashValue(H h, const CollidingKey& k) {
    return H::combine(std::move(h), k.v % 7);  // 1000 keys on 7 hashes
  }
};

}  // namespace

TEST_CASE("equal keys: sets whole, indices ascending, collisions split, on the parallel path", "[common]") {
  constexpr size_t kItems = 100000;  // over kParallelMinItems
  static_assert(kItems >= girtd::kParallelMinItems);
  auto key_of = [](size_t i) { return CollidingKey{int((i * 7919) % 1000)}; };
  std::map<int, std::vector<uint32_t>> expected;
  for (size_t i = 0; i < kItems; ++i) expected[key_of(i).v].push_back(uint32_t(i));

  std::map<int, std::vector<uint32_t>> got;
  size_t sets = 0;
  girtd::for_each_equal_key(kItems, key_of, [&](const uint32_t* index, size_t n) {
    ++sets;
    const int k = key_of(index[0]).v;
    CHECK(got.count(k) == 0);  // each key's set comes once
    got[k].assign(index, index + n);
  });
  CHECK(sets == 1000);
  CHECK(got == expected);  // the same members, in ascending order
}

TEST_CASE("equal keys: -0.0 and 0.0 are one key, as under operator<", "[common]") {
  const std::vector<double> v = {0.0, -0.0, 1.0, -0.0};
  std::vector<std::vector<uint32_t>> sets;
  girtd::for_each_equal_key(v.size(), [&](size_t i) { return girtd::same_zero(v[i]); },
                            [&](const uint32_t* index, size_t n) { sets.emplace_back(index, index + n); });
  std::sort(sets.begin(), sets.end());
  CHECK(sets == std::vector<std::vector<uint32_t>>{{0, 1, 3}, {2}});
}
