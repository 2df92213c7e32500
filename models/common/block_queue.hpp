// A FIFO queue kept in one contiguous block: push at the back, retire from
// the front, index from the front. Retired entries are dropped in bulk, so
// both ends are amortized O(1) with no allocation per entry (std::deque's
// cost a tenth of the timing model's instructions).
#pragma once

#include <cassert>
#include <cstddef>
#include <vector>

namespace girtd {

template <class T>
class BlockQueue {
 public:
  void push_back(const T& v) { items_.push_back(v); }
  // A new, value-initialized entry at the back, for the caller to fill in
  // place (a whole entry built aside and copied can stall on store forwarding).
  T& push_back_slot() { return items_.emplace_back(); }
  void pop_front() {
    assert(!empty());
    if (++head_ >= kCompactAfter && head_ * 2 >= items_.size()) {
      items_.erase(items_.begin(), items_.begin() + std::ptrdiff_t(head_));
      head_ = 0;
    }
  }
  void clear() {
    items_.clear();
    head_ = 0;
  }
  bool empty() const { return head_ == items_.size(); }
  size_t size() const { return items_.size() - head_; }
  const T& front() const {
    assert(!empty());
    return items_[head_];
  }
  const T& back() const {
    assert(!empty());
    return items_.back();
  }
  const T& operator[](size_t i) const {
    assert(i < size());
    return items_[head_ + i];
  }

 private:
  static constexpr size_t kCompactAfter = 1024;
  std::vector<T> items_;
  size_t head_ = 0;  // items_[0 .. head_) are retired
};

}  // namespace girtd
