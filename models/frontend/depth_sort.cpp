#include "frontend/depth_sort.hpp"

#include <algorithm>
#include <unordered_map>

namespace girtd {

void DepthSorter::sort(std::vector<SortItem>& items) {
  auto farther = [&](const SortItem& a, const SortItem& b) {
    ++comparisons_;
    return a.key > b.key;
  };
  std::unordered_map<uint64_t, size_t> where;
  for (size_t i = 0; i < items.size(); ++i) where[items[i].id] = i;
  std::vector<SortItem> ordered;
  ordered.reserve(items.size());
  std::vector<bool> taken(items.size(), false);
  for (uint64_t id : previous_) {
    auto it = where.find(id);
    if (it == where.end() || taken[it->second]) continue;
    taken[it->second] = true;
    ordered.push_back(items[it->second]);
  }
  // Less than half known from last frame: coherence does not pay, sort afresh.
  const bool coherent = !ordered.empty() && 2 * ordered.size() >= items.size();
  if (!coherent) {
    ++full_sorts_;
    std::stable_sort(items.begin(), items.end(), farther);
  } else {
    for (size_t i = 0; i < items.size(); ++i)
      if (!taken[i]) ordered.push_back(items[i]);
    for (size_t i = 1; i < ordered.size(); ++i)
      for (size_t j = i; j > 0 && farther(ordered[j], ordered[j - 1]); --j) std::swap(ordered[j], ordered[j - 1]);
    items.swap(ordered);
  }
  previous_.clear();
  for (const SortItem& s : items) previous_.push_back(s.id);
}

}  // namespace girtd
