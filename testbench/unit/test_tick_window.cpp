// The timing models' tick queue against counting by hand over a plain list.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <random>

#include "timing/tick_window.hpp"

namespace girtd {

TEST_CASE("Tick window: counts below a tick, worked by hand", "[timing]") {
  TickWindow w;
  for (uint64_t t : {3, 5, 5, 9}) w.push_back(t);
  CHECK(w.count_below(5) == 1);
  CHECK(w.count_below(6) == 3);
  CHECK(w.count_below(4) == 1);  // a tick lower than the last asked
  CHECK(w.count_below(100) == 4);
  w.pop_front();  // 3 retired
  CHECK(w.size() == 3);
  CHECK(w.front() == 5);
  CHECK(w.count_below(6) == 2);
  CHECK(w.count_below(0) == 0);
}

TEST_CASE("Tick window: the same counts as a plain queue over a long run", "[timing]") {
  std::mt19937_64 rng(7);
  TickWindow w;
  std::deque<uint64_t> plain;
  uint64_t tick = 0, asked = 0;
  for (int step = 0; step < 200000; ++step) {
    const auto r = rng() % 10;
    if (r < 4) {
      tick += rng() % 3;  // rising, with repeats
      w.push_back(tick);
      plain.push_back(tick);
    } else if (r < 6 && !plain.empty()) {
      w.pop_front();
      plain.pop_front();
    } else if (r < 7) {  // several at once
      const size_t n = std::min<size_t>(plain.size(), rng() % 5);
      w.drop_front(n);
      plain.erase(plain.begin(), plain.begin() + std::ptrdiff_t(n));
    } else {
      // Mostly rising questions, now and then one far back.
      asked = (rng() % 16 == 0) ? rng() % (tick + 1) : asked + rng() % 4;
      const auto expected = size_t(std::count_if(plain.begin(), plain.end(), [&](uint64_t t) { return t < asked; }));
      REQUIRE(w.count_below(asked) == expected);
    }
    REQUIRE(w.size() == plain.size());
    if (!plain.empty()) REQUIRE((w.front() == plain.front() && w.back() == plain.back()));
  }
}

}  // namespace girtd
