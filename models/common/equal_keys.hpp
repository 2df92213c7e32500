// Groups items by an exact key, for the front end's "same surface and
// bit-identical position" matches (shared normals, interior edges, the
// model's welded vertices). A tree keyed by doubles cost a node allocation
// and a dozen cache misses per item; here each item is a 16-byte (hash,
// index) pair, sorted once, and items whose hashes match are compared by
// their keys, so a hash collision never merges two keys.
// Keys compare with ==: -0.0 and 0.0 are one key (hash them through
// `same_zero`), as they were under the tree's <.
#pragma once

#include <absl/hash/hash.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace girtd {

// -0.0 and +0.0 hash alike (== holds between them).
inline double same_zero(double v) { return v + 0.0; }

// Calls group(indices, count) once per set of items 0..n-1 with equal keys,
// the indices ascending within a set; sets in no stated order. `key_of(i)`
// returns a value with == and absl::Hash.
template <class KeyOf, class Group>
void for_each_equal_key(size_t n, KeyOf key_of, Group group) {
  if (n > UINT32_MAX) throw std::length_error("for_each_equal_key: more than 2^32 items");
  struct Item {
    uint64_t hash;
    uint32_t index;
  };
  std::vector<Item> items(n);
  for (size_t i = 0; i < n; ++i) items[i] = {absl::Hash<decltype(key_of(i))>{}(key_of(i)), uint32_t(i)};
  std::sort(items.begin(), items.end(),
            [](const Item& a, const Item& b) { return a.hash != b.hash ? a.hash < b.hash : a.index < b.index; });
  std::vector<uint32_t> set, rest;
  for (size_t at = 0; at < n;) {
    size_t end = at + 1;
    while (end < n && items[end].hash == items[at].hash) ++end;
    rest.clear();
    for (size_t k = at; k < end; ++k) rest.push_back(items[k].index);
    // Usually one key per hash: one pass. A collision splits the run.
    while (!rest.empty()) {
      const auto first = key_of(rest.front());
      set.clear();
      size_t kept = 0;
      for (uint32_t i : rest) {
        if (key_of(i) == first) set.push_back(i);
        else rest[kept++] = i;
      }
      rest.resize(kept);
      group(set.data(), set.size());
    }
    at = end;
  }
}

}  // namespace girtd
