// The machine's cores for work whose answer does not depend on how it is
// split: oneTBB's loops and sorts, always entered from a thread of their own.
// The caller may be a SystemC process running on a small coroutine stack that
// oneTBB cannot see (it sizes its nesting by the thread's real stack); small
// inputs stay on the caller's thread, where a thread would cost more than it saves.
// A process forked from one that ran oneTBB (the Python module renders the
// timed back ends in a forked child) runs everything on its one thread:
// oneTBB's workers do not survive a fork, and its locks may not either.
#pragma once

#include <pthread.h>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>

namespace girtd {

inline constexpr size_t kParallelMinItems = 1 << 16;

// False in a forked child (set by the fork itself, before the child runs).
inline std::atomic<bool> parallel_allowed{true};
inline const bool parallel_fork_guard = [] {
  pthread_atfork(nullptr, nullptr, [] { parallel_allowed.store(false, std::memory_order_relaxed); });
  return true;
}();

inline bool go_parallel(size_t n) { return n >= kParallelMinItems && parallel_allowed.load(std::memory_order_relaxed); }

// Runs `work` on a thread of its own and waits; rethrows what it threw.
template <class Work>
void on_own_thread(Work&& work) {
  std::exception_ptr failed;
  std::thread t([&] {
    try {
      work();
    } catch (...) {
      failed = std::current_exception();
    }
  });
  t.join();
  if (failed) std::rethrow_exception(failed);
}

// body(i) for every i in [0, n), on every core. The calls must not depend
// on each other.
template <class Body>
void parallel_for_each_index(size_t n, Body body) {
  if (!go_parallel(n)) {
    for (size_t i = 0; i < n; ++i) body(i);
    return;
  }
  on_own_thread([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) body(i);
    });
  });
}

// Sorts by `less`, which must be a total order (no two items equal): the
// result is then the same however the work is split.
template <class It, class Less>
void parallel_sort_total(It first, It last, Less less) {
  if (!go_parallel(size_t(last - first))) return std::sort(first, last, less);
  on_own_thread([&] { tbb::parallel_sort(first, last, less); });
}

}  // namespace girtd
