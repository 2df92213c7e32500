// report.html's FIFO occupancy series from pixel stays, worked by hand.
#include <catch2/catch.hpp>

#include <vector>

#include "fifo/fifo_levels.hpp"

namespace girtd {

TEST_CASE("FIFO levels from push and pop ticks: the largest count in each bin", "[report]") {
  // 0.25 us ticks: 4 to a 1 us bin. A pixel pushed on p and popped on q is in
  // the FIFO on ticks p+1 .. q. Stays (0,5) (1,6) (2,9) (10,11) give counts
  // t1 1, t2 2, t3-t5 3, t6 2, t7-t9 1, t10 0, t11 1, then 0.
  FifoLevels levels(0.25e-6);
  levels.interval(0, 5);
  levels.interval(1, 6);
  levels.interval(2, 9);
  levels.interval(10, 11);
  const FifoSeries s = levels.series(16);
  REQUIRE(s.bin_s() == Approx(1e-6));
  std::vector<double> peaks;
  for (const auto& bin : s.bins()) peaks.push_back(bin[0]);
  // Bins: ticks 0-3, 4-7, 8-11, 12-15 (and the instant 16 the run ends).
  CHECK(std::vector<double>(peaks.begin(), peaks.begin() + 4) == std::vector<double>{3, 3, 1, 0});
}

TEST_CASE("FIFO levels read as counts give the same series as stays", "[report]") {
  FifoLevels stays(0.25e-6), counts(0.25e-6);
  stays.interval(0, 5);
  stays.interval(1, 6);
  stays.interval(2, 9);
  stays.interval(10, 11);
  const int count_at[] = {0, 1, 2, 3, 3, 3, 2, 1, 1, 1, 0, 1, 0, 0, 0, 0};
  for (int t = 0; t < 16; ++t) counts.level(uint64_t(t), uint64_t(count_at[t]));
  CHECK(stays.series(16).bins() == counts.series(16).bins());
}

TEST_CASE("FIFO levels: a peak early in a bin does not spill into the bins after it", "[report]") {
  // Pixel i pushed on tick i and popped on 16 + i (i = 0..15) is in on ticks
  // i+1 .. 16+i: the count is t on ticks 1..16, then 32 - t down to 0 on 32;
  // nothing after up to tick 400. Bins of 4 ticks hold the count on their last
  // tick while it rises (3, 7, 11, 15), 16, then the count on their first tick.
  FifoLevels levels(0.25e-6);
  for (uint64_t i = 0; i < 16; ++i) levels.interval(i, 16 + i);
  const FifoSeries s = levels.series(400);
  REQUIRE(s.bins().size() >= 100);
  std::vector<double> peaks;
  for (size_t b = 0; b < 10; ++b) peaks.push_back(s.bins()[b][0]);
  CHECK(peaks == std::vector<double>{3, 7, 11, 15, 16, 12, 8, 4, 0, 0});
  CHECK(s.bins()[99][0] == 0);
}

}  // namespace girtd
