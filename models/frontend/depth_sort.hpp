// Depth sort for transparency and antialiasing (thesis 4.2.6, 4.3.10):
// triangles leave farthest first, so a blended pixel (fringe or T < 1) is
// blended over what lies behind it. Key: the triangle's farthest vertex Zp
// (the thesis gives none; the farthest vertex is the usual painter's key).
//
// The first frame, or one sharing less than half its triangles (by id) with
// the previous frame, gets a full std::stable_sort. Other frames start from
// the previous frame's order (items matched by id; newcomers appended) and
// insertion-sort it: adjacent compare-and-swap, the bubble pass in its
// cheapest form, n - 1 comparisons when nothing moved. A frame where much
// moved (a model turning round) would cost up to n^2/2: after
// coherent_budget(n) comparisons the pass stops and the frame gets the full
// sort instead (counted in full_sorts; the pass's comparisons still count).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace girtd {

struct SortItem {
  uint64_t id = 0;  // the same triangle has the same id in every frame
  double key = 0;   // larger = farther = earlier
  uint32_t index = 0;  // the caller's payload (position in its list)
};

// What the coherent pass may spend before it gives up: n ceil(log2 n) + n
// (about a full sort's cost; more than the n - 1 of an unchanged frame).
uint64_t coherent_budget(size_t n);

class DepthSorter {
 public:
  // Sorts `items` (farthest first) and remembers the order for the next frame.
  void sort(std::vector<SortItem>& items);
  uint64_t comparisons() const { return comparisons_; }
  uint64_t full_sorts() const { return full_sorts_; }
  void forget() { previous_.clear(); }

 private:
  std::vector<uint64_t> previous_;
  uint64_t comparisons_ = 0, full_sorts_ = 0;
};

}  // namespace girtd
