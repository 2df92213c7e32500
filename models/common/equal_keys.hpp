// Groups items by an exact key, for the front end's "same surface and
// bit-identical position" matches (shared normals, interior edges). A tree
// keyed by doubles cost a node allocation and a dozen cache misses per item;
// here each item is a 16-byte (hash, index) pair, hashed and sorted on every
// core (common/parallel.hpp), and only items whose hashes match are compared by their
// keys, so a hash collision never merges two keys. The sets are the same,
// and in the same order, on any number of cores.
// Keys compare with ==: -0.0 and 0.0 are one key (hash them through
// `same_zero`), as they were under the tree's <.
#pragma once

#include <absl/hash/hash.h>

#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "common/parallel.hpp"

namespace girtd {

// -0.0 and +0.0 hash alike (== holds between them).
inline double same_zero(double v) { return v + 0.0; }

// Calls group(indices, count) once per set of items 0..n-1 with equal keys,
// the indices ascending within a set; the sets in the order of their hashes.
// `key_of(i)` returns a value with == and absl::Hash; it is called once per
// item for the hash and once more only for items whose hash is not unique.
template <class KeyOf, class Group>
void for_each_equal_key(size_t n, KeyOf key_of, Group group) {
  if (n > UINT32_MAX) throw std::length_error("for_each_equal_key: more than 2^32 items");
  using Key = decltype(key_of(size_t{0}));
  struct Item {
    uint64_t hash;
    uint32_t index;
  };
  std::vector<Item> items(n);
  parallel_for_each_index(n, [&](size_t i) { items[i] = {absl::Hash<Key>{}(key_of(i)), uint32_t(i)}; });
  parallel_sort_total(items.begin(), items.end(),
                      [](const Item& a, const Item& b) { return a.hash != b.hash ? a.hash < b.hash : a.index < b.index; });
  std::vector<std::pair<Key, uint32_t>> run;
  std::vector<uint32_t> set;
  for (size_t at = 0; at < n;) {
    size_t end = at + 1;
    while (end < n && items[end].hash == items[at].hash) ++end;
    if (end == at + 1) {  // a unique hash is a unique key
      group(&items[at].index, 1);
      at = end;
      continue;
    }
    run.clear();
    for (size_t k = at; k < end; ++k) run.emplace_back(key_of(items[k].index), items[k].index);
    // Usually one key per hash: one pass. A collision splits the run.
    for (size_t first = 0; first < run.size(); ++first) {
      if (run[first].second == UINT32_MAX) continue;  // taken by an earlier key's set
      set.clear();
      for (size_t k = first; k < run.size(); ++k)
        if (run[k].second != UINT32_MAX && run[k].first == run[first].first) {
          set.push_back(run[k].second);
          if (k != first) run[k].second = UINT32_MAX;
        }
      run[first].second = UINT32_MAX;
      group(set.data(), set.size());
    }
    at = end;
  }
}

}  // namespace girtd
