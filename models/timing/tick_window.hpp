// A queue of rising ticks kept in one contiguous block. The FIFO models push
// at the back, retire from the front and ask how many ticks lie below a
// tick, a few times per pixel; the ticks asked about mostly rise too, so a
// cursor answers from where the last answer ended (a binary search over a
// std::deque was the approx back end's hottest function).
#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace girtd {

class TickWindow {
 public:
  void push_back(uint64_t tick) { ticks_.push_back(tick); }
  void pop_front() { drop_front(1); }
  void drop_front(size_t n) {
    assert(n <= size());
    head_ += n;
    // Retired entries are dropped in bulk: amortized O(1), the block stays small.
    if (head_ >= kCompactAfter && head_ * 2 >= ticks_.size()) {
      ticks_.erase(ticks_.begin(), ticks_.begin() + std::ptrdiff_t(head_));
      cursor_ -= std::min(cursor_, head_);
      head_ = 0;
    }
  }
  void clear() {
    ticks_.clear();
    head_ = cursor_ = 0;
  }
  bool empty() const { return head_ == ticks_.size(); }
  size_t size() const { return ticks_.size() - head_; }
  uint64_t front() const { return ticks_[head_]; }
  uint64_t back() const { return ticks_.back(); }
  uint64_t operator[](size_t i) const { return ticks_[head_ + i]; }
  // How many held ticks are below `tick` (they rise). From the last
  // answer's end forward; a tick below the last one asked searches anew.
  size_t count_below(uint64_t tick) const {
    if (cursor_ < head_ || (cursor_ > head_ && ticks_[cursor_ - 1] >= tick))
      cursor_ = size_t(std::lower_bound(ticks_.begin() + std::ptrdiff_t(head_), ticks_.end(), tick) - ticks_.begin());
    while (cursor_ < ticks_.size() && ticks_[cursor_] < tick) ++cursor_;
    return cursor_ - head_;
  }

 private:
  static constexpr size_t kCompactAfter = 1024;
  std::vector<uint64_t> ticks_;
  size_t head_ = 0;            // ticks_[0 .. head_) are retired
  mutable size_t cursor_ = 0;  // ticks_[head_ .. cursor_) were below the last tick asked about
};

}  // namespace girtd
