// Small statistics the benches share.
#pragma once

#include <algorithm>
#include <vector>

namespace girtd {

// The middle value (the upper one of an even count); 0 for none.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// `pairs` times `a` and `b`, one after the other, each first every other
// time (a drift in this shared machine's speed then falls on both alike),
// then `pair_done`. Each run returns false when it failed: that stops it all,
// and run_pairs returns false.
template <typename A, typename B, typename Done>
bool run_pairs(int pairs, A&& a, B&& b, Done&& pair_done) {
  for (int i = 0; i < pairs; ++i) {
    const bool ok = i % 2 ? b() && a() : a() && b();
    if (!ok) return false;
    pair_done();
  }
  return true;
}

}  // namespace girtd
