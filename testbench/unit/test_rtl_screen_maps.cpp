// The rtl heat maps' attribution of pushed pixels to triangles, worked by
// hand: pixels still in the DDA's output stages at a load stay with the
// triangle that emitted them.
#include <catch2/catch.hpp>

#include "rtl/rtl_screen_maps.hpp"

namespace girtd {
namespace {

uint8_t waste_at(const ScreenMaps& m, int x, int y) { return m.dda_waste[size_t(y) * size_t(m.width) + size_t(x)]; }

}  // namespace

TEST_CASE("rtl heat maps: a triangle's pixels pushed after the next load stay its own", "[report]") {
  RtlScreenMaps maps(Params::defaults());
  maps.begin_frame();
  maps.loaded(0, 0);  // A
  maps.pushed(0, 0);
  maps.pushed(1, 0);
  maps.loaded(10, 1);  // B; one of A's pixels still in the output stages
  maps.pushed(2, 0);   // A's third
  maps.pushed(5, 5);   // B's
  maps.idle(14);
  const ScreenMaps& m = maps.maps();
  // A: 10 clocks, 3 pixels: 254 x 7 / 10 = 177; B: 4 clocks, 1 pixel: 254 x 3 / 4 = 190.
  for (int x = 0; x < 3; ++x) CHECK(waste_at(m, x, 0) == 177);
  CHECK(waste_at(m, 3, 0) == ScreenMaps::kNone);
  CHECK(waste_at(m, 5, 5) == 190);
  uint64_t misses = 0;
  for (uint32_t c : m.page_misses) misses += c;
  CHECK(misses == 2);  // (0..2, 0) share a page; (5, 5) is on another
}

TEST_CASE("rtl heat maps: a triangle with no pixels waits behind one still owed pixels", "[report]") {
  RtlScreenMaps maps(Params::defaults());
  maps.begin_frame();
  maps.loaded(0, 0);  // A
  maps.pushed(0, 0);
  maps.loaded(5, 2);  // B; two of A's pixels in flight
  maps.loaded(7, 2);  // C; still A's two: B drew none
  maps.pushed(1, 0);
  maps.pushed(2, 0);
  maps.pushed(9, 9);  // C's
  maps.idle(10);
  const ScreenMaps& m = maps.maps();
  // A: 5 clocks, 3 pixels: 254 x 2 / 5 = 101; C: 3 clocks, 1 pixel: 254 x 2 / 3 = 169.
  for (int x = 0; x < 3; ++x) CHECK(waste_at(m, x, 0) == 101);
  CHECK(waste_at(m, 9, 9) == 169);
}

}  // namespace girtd
