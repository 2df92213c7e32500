// The hardware's derived layouts (models/layout/rtl_layout.hpp) against
// values worked by hand from docs/design.md: the 69-bit FIFO word of fig. 4.17, the
// 16 x 1 page of 4.2.11.4 and other page shapes, the 64-bit VRAM word; the RTL
// build key; and the timing model's cache of several pages.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "config/params.hpp"
#include "layout/rtl_layout.hpp"
#include "layout/rtl_package.hpp"
#include "dda/dda_timing.hpp"

namespace girtd {
namespace {

Params with(const std::string& json) { return Params::with_overrides(nlohmann::json::parse(json), "test"); }

}  // namespace

TEST_CASE("the FIFO word is X10 Y10 R8 G8 B8 nf9 Z16 = 69 bits, X on top", "[layout]") {
  const RtlLayout l = rtl_layout(Params::defaults());
  CHECK(l.screen_bits == 10);
  CHECK(l.fifo.width == 69);
  CHECK(l.fifo.z.lsb == 0);
  CHECK(l.fifo.z.width == 16);
  CHECK(l.fifo.nf.lsb == 16);
  CHECK(l.fifo.nf.width == 9);
  CHECK(l.fifo.b.lsb == 25);
  CHECK(l.fifo.g.lsb == 33);
  CHECK(l.fifo.r.lsb == 41);
  CHECK(l.fifo.y.lsb == 49);
  CHECK(l.fifo.x.lsb == 59);
  CHECK(l.fifo.x.msb() == 68);
  // 0..32 entries need 6 bits; 0..64 need 7 (a 6-bit count never shows a full 64-deep FIFO).
  CHECK(l.fifo_count_bits == 6);
  CHECK(rtl_layout(with(R"({"fifo": {"max_depth": 64}})")).fifo_count_bits == 7);
  CHECK(rtl_layout(with(R"({"fifo": {"max_depth": 256}})")).fifo_count_bits == 9);
  // The DDA's eight states and IDLE = 8 in four bits.
  CHECK(l.dda_idle_state == 8);
  CHECK(l.dda_state_bits == 4);
}

TEST_CASE("the thesis' page: 16 x 1 pixels, page number Y:X[9:4], pixel X[3:0]", "[layout]") {
  const PageGeometry g = rtl_layout(Params::defaults()).page;
  CHECK(g.pixels == 16);
  CHECK(g.index_bits == 4);
  CHECK(g.number_bits == 16);
  // (x, y) = (37, 5): page 5 * 64 + 2 = 322, pixel 5; word address y * 1024 + x.
  CHECK(g.number_of(37, 5) == 322);
  CHECK(g.index_of(37, 5) == 5);
  CHECK(g.vram_address(37, 5) == 5 * 1024 + 37);
  CHECK(g.vram_address(1023, 1023) == (1u << 20) - 1);
}

TEST_CASE("other page shapes: 8 x 2 and 4 x 4", "[layout]") {
  const PageGeometry g8 = rtl_layout(with(R"({"cache": {"page_width": 8, "page_height": 2}})")).page;
  // (37, 5): page row 5 / 2 = 2 of 128 pages a row, column 37 / 8 = 4 -> page 260;
  // in the page: row 5 % 2 = 1, column 37 % 8 = 5 -> 1 * 8 + 5 = 13.
  CHECK(g8.number_of(37, 5) == 260);
  CHECK(g8.index_of(37, 5) == 13);
  CHECK(g8.vram_address(37, 5) == 260 * 16 + 13);
  const PageGeometry g4 = rtl_layout(with(R"({"cache": {"page_width": 4, "page_height": 4}})")).page;
  // (37, 5): page row 1 of 256 a row, column 9 -> 265; in the page row 1, column 1 -> 5.
  CHECK(g4.number_of(37, 5) == 265);
  CHECK(g4.index_of(37, 5) == 5);
  // Every pixel has its own word: the mapping is a permutation of the screen.
  std::vector<bool> seen(size_t{1} << 20, false);
  for (int y = 0; y < 1024; ++y)
    for (int x = 0; x < 1024; ++x) seen[g4.vram_address(x, y)] = true;
  CHECK(std::count(seen.begin(), seen.end(), false) == 0);
}

TEST_CASE("a page shape is refused unless a power of two of 2..64 pixels", "[layout]") {
  CHECK_THROWS_AS(with(R"({"cache": {"page_width": 12}})"), InputError);
  CHECK_THROWS_AS(with(R"({"cache": {"page_width": 64, "page_height": 2}})"), InputError);
  CHECK_THROWS_AS(with(R"({"cache": {"page_width": 1, "page_height": 1}})"), InputError);
  CHECK_THROWS_AS(with(R"({"cache": {"pages": 3}})"), InputError);
  CHECK_NOTHROW(with(R"({"cache": {"page_width": 32, "page_height": 2, "pages": 8}})"));
}

TEST_CASE("the RTL build key changes with what is elaborated, not with run-time inputs", "[layout]") {
  const std::string base = rtl_build_key(Params::defaults());
  CHECK(base.size() == 16);
  CHECK(rtl_build_key(with(R"({"fifo": {"dda_had_depth": 4}})")) == base);  // a port
  CHECK(rtl_build_key(with(R"({"had": {"access_ns": 30}})")) == base);
  CHECK(rtl_build_key(with(R"({"fifo": {"max_depth": 64}})")) != base);
  CHECK(rtl_build_key(with(R"({"ep": {"color": {"frac_bits": 7}}})")) != base);
  CHECK(rtl_build_key(with(R"({"cache": {"pages": 2}})")) != base);
  CHECK(rtl_build_differences(rtl_build_values(Params::defaults()),
                              rtl_build_values(with(R"({"ep": {"color": {"frac_bits": 7}}})"))) ==
        "ep.color.frac_bits 9 -> 7");
}

TEST_CASE("the timing model's cache: pages side by side stay in it together", "[layout][timing]") {
  // Pixels alternate between x = 0 and x = 16: pages 0 and 1 of a 16 x 1 row.
  std::vector<TimedPixel> pixels;
  for (int i = 0; i < 20; ++i) pixels.push_back({uint64_t(i), (i % 2) * 16, 0, HadOutcome::kWritten});
  auto misses = [&](const std::string& cfg) {
    BackendTimingModel m(with(cfg));
    m.begin_frame();
    m.triangle(20, pixels);
    m.end_frame();
    return m.timing().page_misses;
  };
  CHECK(misses(R"({})") == 20);                      // one page: every pixel evicts the other's
  CHECK(misses(R"({"cache": {"pages": 2}})") == 2);  // slots 0 and 1: two cold misses
  // Pages 0 and 64 (x = 0, rows 0 and 1) share slot 0 of two: all miss again.
  std::vector<TimedPixel> column;
  for (int i = 0; i < 20; ++i) column.push_back({uint64_t(i), 0, i % 2, HadOutcome::kWritten});
  BackendTimingModel m(with(R"({"cache": {"pages": 2}})"));
  m.begin_frame();
  m.triangle(20, column);
  m.end_frame();
  CHECK(m.timing().page_misses == 20);
  // A 4 x 4 page holds both rows: one miss.
  BackendTimingModel m4(with(R"({"cache": {"page_width": 4, "page_height": 4}})"));
  m4.begin_frame();
  m4.triangle(20, column);
  m4.end_frame();
  CHECK(m4.timing().page_misses == 1);
}

}  // namespace girtd
