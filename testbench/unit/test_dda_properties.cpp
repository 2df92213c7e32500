// Properties of preparer + DDA on thousands of random triangles (log-uniform
// size up to the full screen): the traversal emits exactly the lattice pixels
// its own D registers call inside, once each; the EP values stay within the
// rounding bound of the exact planes, and that bound is tight (one fraction
// bit fewer breaks it).
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <vector>

#include "common/fixed_point.hpp"
#include "common/triangle_setup.hpp"
#include "dda/dda_datapath.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"
#include "dda/nf_unit.hpp"
#include "backends/screen_maps.hpp"
#include "workloads/random_triangles.hpp"

namespace girtd {
namespace {

// D_i at (x, y) as a register of the D format holds it: exact integer sums, wrapped.
int64_t d_at(const DdaParams& d, int e, int x, int y, const FixFormat& f) {
  return wrap(d.ep[e].v + int64_t(x - d.x0) * d.ep[e].dx + int64_t(y - d.y0) * d.ep[e].dy, f);
}

struct ErrorScan {
  double worst_ratio = 0;  // max over pixels and EPs of |error| / bound
  uint64_t pixels = 0;
  uint64_t overflowed = 0;  // EP values outside their register's range
};

// |EP - exact plane| <= 2^-(F+1) (1 + |x - x0| + |y - y0|): start value and
// each derivative rounded to nearest, errors adding once per unit step.
ErrorScan scan_errors(const Params& p, int triangles, uint32_t seed) {
  DdaPreparer prep(p);
  DdaEngine dda(p);
  std::mt19937 rng(seed);
  ErrorScan scan;
  for (int n = 0; n < triangles; ++n) {
    const Triangle t = random_triangle(rng, 1024);
    FrameSettings f;
    f.q = 1;
    DdaParams d;
    const uint64_t clamped_before = prep.counts().clamped_values();
    if (prep.prepare(t, f, d) != PrepareResult::kReady) continue;
    if (prep.counts().clamped_values() != clamped_before) continue;  // derivative did not fit: not a rounding case
    const TriangleSetup s = *setup_triangle(t);
    dda.run(d, [&](const DdaEmit& e) {
      const double x = e.pixel.x, y = e.pixel.y;
      const double steps = 1 + std::abs(x - d.x0) + std::abs(y - d.y0);
      auto check = [&](int64_t raw, const FixFormat& fmt, double exact, double scale) {
        const double value = scale * exact;
        // A value the register cannot hold wraps (overflow, not rounding): counted apart.
        if (value > to_double(fmt.raw_max(), fmt) || value < to_double(fmt.raw_min(), fmt)) {
          ++scan.overflowed;
          return;
        }
        const double bound = std::ldexp(1.0, -fmt.frac_bits - 1) * steps + 1e-9 * (1 + std::fabs(value));
        scan.worst_ratio = std::max(scan.worst_ratio, std::fabs(to_double(raw, fmt) - value) / bound);
      };
      check(e.raw[kEpR], p.ep_color, s.attr[kR].at(x, y), 1);
      check(e.raw[kEpG], p.ep_color, s.attr[kG].at(x, y), 1);
      check(e.raw[kEpB], p.ep_color, s.attr[kB].at(x, y), 1);
      check(e.raw[kEpT], p.ep_t, s.attr[kT].at(x, y), 256);
      check(e.raw[kEpZ], p.ep_z, s.attr[kZ].at(x, y), 1);
      for (int i = 0; i < 3; ++i) check(e.raw[kEpD1 + i], p.ep_d, s.edge[i].at(x, y), 1);
      ++scan.pixels;
    });
  }
  return scan;
}

}  // namespace

TEST_CASE("DDA emits every inside lattice pixel exactly once and nothing else", "[dda][property]") {
  Params p = Params::defaults();
  std::mt19937 rng(20261122);
  std::uniform_int_distribution<int> pick(0, 3);
  const double qs[4] = {0, 0.5, 1, 2};
  uint64_t total_pixels = 0, triangles = 0;
  for (int n = 0; n < 1500; ++n) {
    p.xy_compare_pipelined = (n % 2) == 1;
    FrameSettings f;
    f.q = qs[pick(rng)];
    const Triangle t = random_triangle(rng, 1024);
    DdaPreparer prep(p);
    DdaParams d;
    if (prep.prepare(t, f, d) != PrepareResult::kReady) continue;
    const NormUnit norm(p.ep_d, p.norm_frac_bits, d.q);
    std::set<std::pair<int, int>> expected;
    for (int y = d.y0; y <= d.ymax; ++y)
      for (int x = d.xmin; x <= d.xmax; ++x)
        if (norm.inside(d_at(d, kEpD1, x, y, p.ep_d)) && norm.inside(d_at(d, kEpD2, x, y, p.ep_d)) &&
            norm.inside(d_at(d, kEpD3, x, y, p.ep_d)))
          expected.insert({x, y});
    std::map<std::pair<int, int>, int> seen;
    bool values_match = true;
    DdaEngine(p).run(d, [&](const DdaEmit& e) {
      ++seen[{e.pixel.x, e.pixel.y}];
      // Path independence: the register equals start + steps x derivative.
      values_match = values_match && e.raw[kEpR] == d_at(d, kEpR, e.pixel.x, e.pixel.y, p.ep_color);
    });
    std::set<std::pair<int, int>> emitted;
    int duplicates = 0;
    for (const auto& [xy, count] : seen) {
      emitted.insert(xy);
      duplicates += count > 1;
    }
    INFO("triangle " << n << " q " << f.q << " start " << d.x0 << "," << d.y0);
    REQUIRE(duplicates == 0);
    REQUIRE(emitted == expected);
    REQUIRE(values_match);
    total_pixels += emitted.size();
    ++triangles;
  }
  CHECK(triangles > 1400);
  CHECK(total_pixels > 1000000);  // the sample reaches large triangles
}

namespace {

// `count` random triangles prepared for the DDA, with Q 0..2, the X/Y compare
// pipelined or not and the walk fixed or as written (DDApix): `check(p, d)`
// for each that the preparer takes.
template <typename Check>
void for_random_walks(int count, uint32_t seed, Check&& check) {
  Params p = Params::defaults();
  std::mt19937 rng(seed);
  const double qs[4] = {0, 0.5, 1, 2};
  for (int n = 0; n < count; ++n) {
    p.xy_compare_pipelined = (n % 2) == 1;
    p.walk_fix = (n % 3) != 0;
    FrameSettings f;
    f.q = qs[rng() % 4];
    const Triangle t = random_triangle(rng, 1024);
    DdaParams d;
    if (DdaPreparer(p).prepare(t, f, d) != PrepareResult::kReady) continue;
    INFO("triangle " << n << " q " << f.q << " pipelined compare " << p.xy_compare_pipelined << " walk_fix "
                     << p.walk_fix);
    check(p, d);
  }
}

}  // namespace

// report.html's DDA-waste map keeps each row of a triangle as one run, its
// lowest and highest x (sim/backends/screen_maps.hpp): that holds because the
// DDA emits a row once, as one streak of neighbours (RIGHT from the row's
// first pixel, then LEFT from beside it; or RUN one way), rows going down.
TEST_CASE("DDA emits each row of a triangle once, as one contiguous streak", "[dda][property]") {
  uint64_t rows = 0;
  for_random_walks(1500, 20261202, [&](const Params& p, const DdaParams& d) {
    std::vector<std::pair<int, int>> px;  // (y, x) in emission order
    DdaEngine(p).run(d, [&](const DdaEmit& e) { px.emplace_back(e.pixel.y, e.pixel.x); });
    for (size_t i = 0; i < px.size();) {
      size_t j = i;
      std::set<int> xs;
      for (; j < px.size() && px[j].first == px[i].first; ++j) xs.insert(px[j].second);
      REQUIRE(xs.size() == j - i);                               // no pixel twice
      REQUIRE(*xs.rbegin() - *xs.begin() + 1 == int(xs.size()));  // no gap
      if (j < px.size()) REQUIRE(px[j].first > px[i].first);     // the row is not visited again
      ++rows;
      i = j;
    }
  });
  CHECK(rows > 80000);
}

// The waste map's rows (ScreenMapRecorder::pixel) against the DDA's pixels
// themselves, one recorder for triangle after triangle: each triangle
// changes exactly the pixels it emitted (a row carried over from the one
// before would change others), to its share of clocks that emitted no pixel,
// counted here from the DDA's clock probe.
TEST_CASE("the DDA-waste map paints exactly the pixels the DDA emitted", "[dda][property][report]") {
  int checked = 0;
  std::optional<ScreenMapRecorder> rec, small_log;  // small_log: painted only as its 64-entry row log fills
  std::vector<uint8_t> before;
  for_random_walks(300, 2026120202, [&](const Params& p, const DdaParams& d) {
    if (!rec) {
      rec.emplace(p);
      rec->begin_frame();
      small_log.emplace(p, 64);
      small_log->begin_frame();
    }
    before = rec->maps().dda_waste;
    std::set<std::pair<int, int>> emitted;
    uint64_t clocks = 0, idle = 0;
    DdaEngine(p).run(
        d,
        [&](const DdaEmit& e) {
          emitted.insert({e.pixel.x, e.pixel.y});
          rec->pixel(e.pixel.x, e.pixel.y);  // drawn(), and the page misses the cache geometry gives
          small_log->pixel(e.pixel.x, e.pixel.y);
        },
        [&](const DdaClock& c) {
          ++clocks;
          idle += !c.emitted;
        });
    rec->end_triangle(clocks, clocks - idle);
    small_log->end_triangle(clocks, clocks - idle);
    const uint8_t waste = uint8_t(254 * idle / clocks);
    const ScreenMaps& m = rec->maps();
    for (const auto& [x, y] : emitted) REQUIRE(m.dda_waste[size_t(y) * size_t(m.width) + size_t(x)] == waste);
    for (size_t i = 0; i < before.size(); ++i)
      if (m.dda_waste[i] != before[i])
        REQUIRE(emitted.count({int(i % size_t(m.width)), int(i / size_t(m.width))}) == 1);
    ++checked;
  });
  CHECK(checked > 250);
  // The same maps, taken in batches as the logs filled (and the rest now).
  CHECK(small_log->maps().dda_waste == rec->maps().dda_waste);
  CHECK(small_log->maps().page_misses == rec->maps().page_misses);
  uint64_t misses = 0;
  for (uint32_t m : rec->maps().page_misses) misses += m;
  CHECK(misses > 1000);  // enough to fill the small log many times
}

TEST_CASE("DDA EP error stays within the rounding bound of the exact planes", "[dda][property]") {
  const ErrorScan scan = scan_errors(Params::defaults(), 600, 7);
  INFO("worst error / bound = " << scan.worst_ratio << " over " << scan.pixels << " pixels, "
                                 << scan.overflowed << " EP values out of range");
  CHECK(scan.pixels > 500000);
  CHECK(scan.worst_ratio <= 1.0);
  CHECK(scan.worst_ratio > 0.5);  // the bound is not loose by more than 2x
  CHECK(scan.overflowed < scan.pixels / 1000);
}

TEST_CASE("DDA error bound is tight: one fraction bit fewer breaks it", "[dda][property]") {
  // Same triangles, colour EPs with 8 instead of 9 fraction bits, judged by
  // the 9-bit bound.
  Params narrow = Params::defaults();
  narrow.ep_color.frac_bits -= 1;
  narrow.ep_color.int_bits += 1;  // same register width, one more integer bit
  const Params p = Params::defaults();
  DdaPreparer prep(narrow);
  DdaEngine dda(narrow);
  std::mt19937 rng(7);
  double worst = 0;
  for (int n = 0; n < 600; ++n) {
    const Triangle t = random_triangle(rng, 1024);
    FrameSettings f;
    DdaParams d;
    const uint64_t before = prep.counts().clamped_values();
    if (prep.prepare(t, f, d) != PrepareResult::kReady || prep.counts().clamped_values() != before) continue;
    const TriangleSetup s = *setup_triangle(t);
    dda.run(d, [&](const DdaEmit& e) {
      const double steps = 1 + std::abs(e.pixel.x - d.x0) + std::abs(e.pixel.y - d.y0);
      const double bound_9bit = std::ldexp(1.0, -p.ep_color.frac_bits - 1) * steps;
      const double err = std::fabs(to_double(e.raw[kEpR], narrow.ep_color) - s.attr[kR].at(e.pixel.x, e.pixel.y));
      worst = std::max(worst, err / bound_9bit);
    });
  }
  CHECK(worst > 1.0);
}


TEST_CASE("may_wrap: the register's extremes over the visited lattice, worked by hand", "[dda][prune]") {
  const Params p = Params::defaults();  // colour EPs 11.9: 20 bits, raw 2^19 - 1 at most
  DdaParams d;
  d.x0 = 0, d.y0 = 0, d.xmin = 0, d.xmax = 9, d.ymax = 0;
  d.ep[kEpR] = {(int64_t{1} << 19) - 100, 10, 0};
  // X from 0 to 9: R reaches 2^19 - 100 + 90 = 2^19 - 10, and at the row
  // past Ymax (Y = 1, dY = 0) the same: it fits.
  CHECK_FALSE(may_wrap(p, d));
  d.xmax = 10;  // 2^19 - 100 + 100 = 2^19: one past the format
  CHECK(may_wrap(p, d));
  d.xmax = 9;
  d.ep[kEpR].dy = 50;  // the row past Ymax: 2^19 - 10 + 50
  CHECK(may_wrap(p, d));
  d.ep[kEpR].dy = -50;  // going down, far from the bottom: -2^19 is far
  CHECK_FALSE(may_wrap(p, d));
  // A start right of the limits' left end, R falling to the left: X = 0 is
  // 5 steps left of x0 = 5, R = -2^19 + 40 - 5 x 10 = -2^19 - 10 there.
  d = DdaParams{};
  d.x0 = 5, d.y0 = 0, d.xmin = 0, d.xmax = 5, d.ymax = 3;
  d.ep[kEpR] = {-(int64_t{1} << 19) + 40, 10, 0};
  CHECK(may_wrap(p, d));
  d.ep[kEpR].v += 10;  // -2^19 exactly at X = 0: fits
  CHECK_FALSE(may_wrap(p, d));
}

TEST_CASE("skipping the wrap detector where nothing can wrap changes no count", "[dda][prune]") {
  // Triangles up to 6,000 px across, so the D EPs (12 integer bits) wrap in
  // some: their numerics must be the same with the skip as without.
  // The sequencer's variants take turns: DDApix as written (no walk fix),
  // an unpipelined compare, far edges as constants, edge flags (hard edges).
  std::mt19937 rng(20261202);
  int safe = 0, unsafe = 0, wrapped = 0;
  for (int n = 0; n < 400; ++n) {
    Params p = Params::defaults();
    p.walk_fix = n % 5 != 1;
    p.xy_compare_pipelined = n % 5 != 2;
    p.far_edges_constant = n % 5 == 3;
    p.edge_flags = n % 5 == 4;
    FrameSettings f;
    f.q = n % 2;
    Triangle t = random_triangle(rng, n % 4 == 0 ? 6000 : 300);
    t.interior_edges = static_cast<uint8_t>(n % 8);
    DdaPreparer prep(p);
    DdaParams d;
    if (prep.prepare(t, f, d) != PrepareResult::kReady) continue;
    (may_wrap(p, d) ? unsafe : safe) += 1;
    DdaEngine full(p), pruned(p);
    pruned.skip_unreachable_wraps(true);
    std::vector<Pixel> a, b;
    const DdaRunStats sa = full.run(d, [&](const DdaEmit& e) { a.push_back(e.pixel); });
    const DdaRunStats sb = pruned.run(d, [&](const DdaEmit& e) { b.push_back(e.pixel); });
    INFO("triangle " << n);
    REQUIRE(sa.cycles == sb.cycles);
    REQUIRE(sa.emitted == sb.emitted);
    for (int i = 0; i < kEpCount; ++i) {
      REQUIRE(sa.numerics.ep[i].wraps == sb.numerics.ep[i].wraps);
      REQUIRE(sa.numerics.ep[i].saturations == sb.numerics.ep[i].saturations);
    }
    REQUIRE(a.size() == b.size());
    for (size_t k = 0; k < a.size(); ++k)
      REQUIRE((a[k].x == b[k].x && a[k].y == b[k].y && a[k].nf == b[k].nf && a[k].r == b[k].r &&
               a[k].g == b[k].g && a[k].b == b[k].b && a[k].z == b[k].z));
    wrapped += sa.numerics.wraps() > 0;
  }
  CHECK(safe > 200);   // the skip is taken
  CHECK(unsafe > 20);  // and refused where a wrap is possible,
  CHECK(wrapped > 5);  // some of which do wrap
}

}  // namespace girtd
