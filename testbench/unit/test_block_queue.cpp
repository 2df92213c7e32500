// The block queue against std::deque over a long random run.
#include <catch2/catch.hpp>

#include <cstdint>
#include <deque>
#include <random>

#include "common/block_queue.hpp"

namespace girtd {

TEST_CASE("Block queue: worked by hand", "[timing]") {
  BlockQueue<int> q;
  for (int v : {3, 5, 9}) q.push_back(v);
  q.pop_front();
  CHECK(q.size() == 2);
  CHECK(q.front() == 5);
  CHECK(q.back() == 9);
  CHECK(q[1] == 9);
  q.clear();
  CHECK(q.empty());
}

TEST_CASE("Block queue: the same entries as a std::deque over a long run, through its compactions", "[timing]") {
  std::mt19937_64 rng(7);
  BlockQueue<uint64_t> q;
  std::deque<uint64_t> plain;
  for (int step = 0; step < 200000; ++step) {
    const uint64_t r = rng() % 10;
    if (r < 5) {
      q.push_back(step);
      plain.push_back(uint64_t(step));
    } else if (!plain.empty()) {
      q.pop_front();
      plain.pop_front();
    }
    REQUIRE(q.size() == plain.size());
    if (!plain.empty()) {
      REQUIRE(q.front() == plain.front());
      REQUIRE(q.back() == plain.back());
      const size_t i = size_t(rng() % plain.size());
      REQUIRE(q[i] == plain[i]);
    }
  }
}

}  // namespace girtd
