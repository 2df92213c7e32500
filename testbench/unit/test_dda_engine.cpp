// The golden DDA's clock-by-clock behaviour on small triangles traced by
// hand (Q = 0, same-cycle compare unless said). Each expected clock is
// "STATE x,y" with '*' when the clock emits; the arithmetic is in comments.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "dda_test_support.hpp"

namespace girtd {
using test::Lin;

namespace {

std::vector<std::string> render_clocks(const test::Trace& t) {
  std::vector<std::string> out;
  for (const DdaClock& c : t.clocks)
    out.push_back(std::string(kDdaStateNames[static_cast<int>(c.state)]) + " " + std::to_string(c.x) + "," +
                  std::to_string(c.y) + (c.emitted ? " *" : ""));
  return out;
}

}  // namespace

// Triangle (2,0) (0,2) (4,2): rows y=0: x=2; y=1: x=1..3; y=2: x=0..4.
// D1 = x + y - 2 (left edge), D2 = -x + y + 2 (right edge), D3 = 2 - y (bottom).
TEST_CASE("DDA zig-zag: hand-traced clock sequence", "[dda]") {
  const Params p = test::ecl_params();
  const DdaParams d = test::make_params(p, 2, 0, 0, 4, 2, Lin{1, 1, -2}, Lin{-1, 1, 2}, Lin{0, -1, 2});
  const test::Trace t = test::run_traced(p, d);
  const std::vector<std::string> expected = {
      "CHECK 2,0",                                     // inside: save AUX
      "RIGHT 2,0 *", "RIGHT 3,0",                      // (3,0): D2 = -1, restore AUX
      "LSTEP 2,0",   "LEFT 1,0",                       // (1,0): D1 = -1, Y++
      "CHECK 1,1",                                     // D1 = 0, D2 = 2, D3 = 1: save
      "RIGHT 1,1 *", "RIGHT 2,1 *", "RIGHT 3,1 *",     // (3,1): D2 = 0 still inside
      "RIGHT 4,1",   "LSTEP 1,1",   "LEFT 0,1",        // (4,1) D2 = -1; (0,1) D1 = -1
      "CHECK 0,2",   "RIGHT 0,2 *", "RIGHT 1,2 *", "RIGHT 2,2 *", "RIGHT 3,2 *",
      "RIGHT 4,2 *",                                   // X = Xmax: emit and restore at once
      "LSTEP 0,2",                                     // X = Xmin: no left half, Y++
      "CHECK 0,3",                                     // Y > Ymax: done
  };
  CHECK(render_clocks(t) == expected);
  CHECK(t.stats.cycles == 20);
  CHECK(t.stats.emitted == 9);
  CHECK(t.stats.wasted() == 11);
}

TEST_CASE("DDA zig-zag with the pipelined X/Y compare costs one clock per run end", "[dda]") {
  Params p = test::ecl_params();
  p.xy_compare_pipelined = true;
  const DdaParams d = test::make_params(p, 2, 0, 0, 4, 2, Lin{1, 1, -2}, Lin{-1, 1, 2}, Lin{0, -1, 2});
  const test::Trace t = test::run_traced(p, d);
  // Same 20 clocks plus a WAIT after each of the 6 run ends (2 per row, 3 rows).
  CHECK(t.stats.cycles == 26);
  CHECK(t.stats.per_state[static_cast<int>(DdaState::kWait)] == 6);
  CHECK(t.stats.emitted == 9);
}

// Triangle (0,0) (3,0) (6,3): rows y=0: x=0..3; y=1: 2..4; y=2: 4..5; y=3: 6.
// D1 = x - 2y (left), D2 = y (top), D3 = 3 - x + y (right).
TEST_CASE("DDA walks right (DIR = sign of D1'x > 0): hand-traced clock sequence", "[dda]") {
  const Params p = test::ecl_params();
  const DdaParams d = test::make_params(p, 0, 0, 0, 6, 3, Lin{1, -2, 0}, Lin{0, 1, 0}, Lin{-1, 1, 3});
  const test::Trace t = test::run_traced(p, d);
  const std::vector<std::string> expected = {
      "CHECK 0,0", "RIGHT 0,0 *", "RIGHT 1,0 *", "RIGHT 2,0 *", "RIGHT 3,0 *",
      "RIGHT 4,0",                   // D3 = -1: restore to (0,0)
      "LSTEP 0,0",                   // X = Xmin: Y++
      "CHECK 0,1",                   // D1 = -2 < 0, D1'x = +1: walk right
      "WALK 1,1",  "WALK 2,1",       // (2,1): D1 = 0 inside: save
      "RUN 2,1 *", "RUN 3,1 *", "RUN 4,1 *",
      "RUN 5,1",                     // D3 = -1: restore to (2,1)
      "YSTEP 2,1", "CHECK 2,2", "WALK 3,2", "WALK 4,2", "RUN 4,2 *", "RUN 5,2 *", "RUN 6,2",
      "YSTEP 4,2", "CHECK 4,3", "WALK 5,3", "WALK 6,3",
      "RUN 6,3 *",                   // X = Xmax: emit and restore at once
      "YSTEP 6,3", "CHECK 6,4",
  };
  CHECK(render_clocks(t) == expected);
  CHECK(t.stats.emitted == 10);
  CHECK(t.stats.cycles == 28);
}

// Triangle (6,0) (0,3) (2,3): rows y=0: x=6; y=1: 4; y=2: 2..3; y=3: 0..2.
// D1 = x + 2y - 6 (left), D2 = 18 - 3x - 4y (right, x 3), D3 = 3 - y (bottom).
TEST_CASE("DDA walks left (DIR = sign of D2'x < 0): hand-traced clock sequence", "[dda]") {
  const Params p = test::ecl_params();
  const DdaParams d = test::make_params(p, 6, 0, 0, 6, 3, Lin{1, 2, -6}, Lin{-3, -4, 18}, Lin{0, -1, 3});
  const test::Trace t = test::run_traced(p, d);
  const std::vector<std::string> expected = {
      "CHECK 6,0", "RIGHT 6,0 *", "LSTEP 6,0", "LEFT 5,0",  // (5,0): D1 = -1
      "CHECK 5,1",                                          // D2 = 18-15-4 = -1, D2'x = -3: walk left
      "WALK 4,1",                                           // D2 = 2, D1 = 0: save
      "RUN 4,1 *", "RUN 3,1",                               // (3,1): D1 = -1
      "YSTEP 4,1", "CHECK 4,2", "WALK 3,2", "RUN 3,2 *", "RUN 2,2 *", "RUN 1,2",
      "YSTEP 3,2", "CHECK 3,3", "WALK 2,3", "RUN 2,3 *", "RUN 1,3 *",
      "RUN 0,3 *",                                          // X = Xmin: emit and restore
      "YSTEP 2,3", "CHECK 2,4",
  };
  CHECK(render_clocks(t) == expected);
  CHECK(t.stats.emitted == 7);
}

// Triangle (2,2) (6,0) (6,4) entered at (0,2), left of its left vertex, where
// two distances are negative: D1 = x + 2y - 6 = -2, D2 = x - 2y + 2 = -2, both
// with D'x = +1, so DIR is right. D3 = 6 - x.
TEST_CASE("DDA DIR at a vertex: two negative distances of the same sign", "[dda]") {
  const Params p = test::ecl_params();
  const DdaParams d = test::make_params(p, 0, 2, 0, 6, 4, Lin{1, 2, -6}, Lin{1, -2, 2}, Lin{-1, 0, 6});
  const test::Trace t = test::run_traced(p, d);
  REQUIRE(t.clocks.size() > 2);
  CHECK(t.clocks[0].state == DdaState::kCheck);
  CHECK(t.clocks[1].state == DdaState::kWalk);
  CHECK(t.clocks[1].x == 1);  // moved right
  // Row 2: x = 2..6; row 3: D2 = x - 4 >= 0 -> x = 4..6; row 4: D2 = x - 6 -> x = 6.
  const std::vector<std::pair<int, int>> expected = {{2, 2}, {3, 2}, {4, 2}, {5, 2}, {6, 2},
                                                     {4, 3}, {5, 3}, {6, 3}, {6, 4}};
  CHECK(t.pixels == expected);
}

TEST_CASE("DDApix as written skips the row of an outside start, the fix walks into it", "[dda]") {
  // The walk-right triangle entered at (0,1), outside (D1 = -2).
  Params p = test::ecl_params();
  const DdaParams d = test::make_params(p, 0, 1, 0, 6, 3, Lin{1, -2, 0}, Lin{0, 1, 0}, Lin{-1, 1, 3});
  const test::Trace fixed = test::run_traced(p, d);
  CHECK(fixed.pixels.size() == 6);  // rows 1..3: 3 + 2 + 1
  p.walk_fix = false;
  const test::Trace as_written = test::run_traced(p, d);
  CHECK(as_written.pixels.size() == 3);  // row 1 skipped: rows 2..3 only
  CHECK(as_written.pixels.front() == std::make_pair(4, 2));
}

TEST_CASE("DDA outputs saturate at 0 and 255", "[dda]") {
  const Params p = test::ecl_params();
  // One row y = 0, x = 0..3: D1 = x, D2 = 3 - x, D3 = -y.
  DdaParams d = test::make_params(p, 0, 0, 0, 3, 0, Lin{1, 0, 0}, Lin{-1, 0, 3}, Lin{0, -1, 0});
  d.ep[kEpR] = {250 * p.ep_color.one(), 3 * p.ep_color.one(), 0};  // 250, 253, 256, 259
  d.ep[kEpG] = {2 * p.ep_color.one(), -1 * p.ep_color.one(), 0};   // 2, 1, 0, -1
  std::vector<Pixel> px;
  DdaEngine(p).run(d, [&](const DdaEmit& e) { px.push_back(e.pixel); });
  REQUIRE(px.size() == 4);
  CHECK(int(px[0].r) == 250);
  CHECK(int(px[1].r) == 253);
  CHECK(int(px[2].r) == 255);  // 256 saturates
  CHECK(int(px[3].r) == 255);  // 259 saturates
  CHECK(int(px[2].g) == 0);
  CHECK(int(px[3].g) == 0);    // -1 saturates to 0, does not wrap to 255
  CHECK(px[0].nf == 256);      // inside, opaque: U = 0
}

TEST_CASE("DDA emits at the state clock plus the output-register latency", "[dda]") {
  Params p = test::ecl_params();
  p.output_latency_clocks = 2;
  const DdaParams d = test::make_params(p, 2, 0, 0, 4, 2, Lin{1, 1, -2}, Lin{-1, 1, 2}, Lin{0, -1, 2});
  std::vector<uint64_t> cycles;
  DdaEngine(p).run(d, [&](const DdaEmit& e) { cycles.push_back(e.cycle); });
  // The zig-zag trace emits on clocks 1, 6, 7, 8, 13..17.
  CHECK(cycles == std::vector<uint64_t>{3, 8, 9, 10, 15, 16, 17, 18, 19});
}

}  // namespace girtd
