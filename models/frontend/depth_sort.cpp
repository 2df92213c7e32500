#include "frontend/depth_sort.hpp"

#include <absl/container/flat_hash_map.h>

#include <algorithm>

namespace girtd {
namespace {

// Insertion sort (adjacent compare-and-swap) that gives up after `budget`
// comparisons; true when it finished.
template <typename Farther>
bool insertion_sort(std::vector<SortItem>& v, Farther farther, uint64_t budget) {
  uint64_t used = 0;
  for (size_t i = 1; i < v.size(); ++i)
    for (size_t j = i; j > 0; --j) {
      if (used++ == budget) return false;
      if (!farther(v[j], v[j - 1])) break;
      std::swap(v[j], v[j - 1]);
    }
  return true;
}

}  // namespace

uint64_t coherent_budget(size_t n) {
  uint64_t log2n = 0;
  while ((uint64_t{1} << log2n) < n) ++log2n;
  return static_cast<uint64_t>(n) * log2n + n;
}

void DepthSorter::sort(std::vector<SortItem>& items) {
  auto farther = [&](const SortItem& a, const SortItem& b) {
    ++comparisons_;
    return a.key > b.key;
  };
  std::vector<SortItem> ordered;
  std::vector<bool> taken(items.size(), false);
  if (!previous_.empty()) {  // the first frame has nothing to match
    absl::flat_hash_map<uint64_t, size_t> where;
    where.reserve(items.size());
    for (size_t i = 0; i < items.size(); ++i) where[items[i].id] = i;
    ordered.reserve(items.size());
    for (uint64_t id : previous_) {
      auto it = where.find(id);
      if (it == where.end() || taken[it->second]) continue;
      taken[it->second] = true;
      ordered.push_back(items[it->second]);
    }
  }
  // Less than half known from last frame: coherence does not pay, sort afresh.
  bool sorted = false;
  if (!ordered.empty() && 2 * ordered.size() >= items.size()) {
    for (size_t i = 0; i < items.size(); ++i)
      if (!taken[i]) ordered.push_back(items[i]);
    sorted = insertion_sort(ordered, farther, coherent_budget(ordered.size()));
    if (sorted) items.swap(ordered);
  }
  if (!sorted) {
    ++full_sorts_;
    std::stable_sort(items.begin(), items.end(), farther);
  }
  previous_.clear();
  for (const SortItem& s : items) previous_.push_back(s.id);
}

}  // namespace girtd
