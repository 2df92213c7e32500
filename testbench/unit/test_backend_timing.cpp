// The back end's event timing model (models/timing) against the RTL back end
// (hw/backend) on the sample traces: the same page misses, DDA waits and
// tick count.
#include <catch2/catch.hpp>

#include "rtl/timing_comparison.hpp"

namespace girtd {
namespace {

void check_trace(const std::string& path, const Params& p = Params::defaults()) {
  const TimingComparison c = compare_timing(p, path);
  INFO(path << ": model " << c.model.ticks << " ticks, RTL " << c.rtl.ticks << "; misses " << c.model.page_misses
            << " / " << c.rtl.page_misses << "; DDA waits " << c.model.dda_wait_clocks << " / "
            << c.rtl.dda_wait_ticks / 7);
  CHECK(c.model.page_misses == c.rtl.page_misses);
  CHECK(c.model.pixels == c.rtl.pixels_generated);
  CHECK(c.model.dda_wait_clocks * 7 == c.rtl.dda_wait_ticks);  // 7 ticks per DDA clock (35 ns / 5 ns)
  CHECK(c.model.ticks == c.rtl.ticks);
  CHECK(c.model.had_busy_ticks == c.rtl.had_busy_ticks);
  CHECK(c.model.had_vram_wait_ticks == c.rtl.had_vram_wait_ticks);
}

// The memory-side options the model covers, alone and together (run-time
// inputs of the built RTL).
void check_memory_options(const std::string& path) {
  for (const auto& [wb, dirty] : {std::pair{true, false}, {false, true}, {true, true}}) {
    INFO("write_behind " << wb << ", dirty_bits " << dirty);
    check_trace(path, Params::with_overrides({{"had", {{"write_behind", wb}, {"dirty_bits", dirty}}}}, "test"));
  }
}

}  // namespace

TEST_CASE("timing model matches the RTL back end: 200-pixel triangles", "[timing]") {
  check_trace("traces/equilateral_200.trace");
}
TEST_CASE("timing model matches the RTL back end: z_overlap", "[timing]") { check_trace("traces/z_overlap.trace"); }
TEST_CASE("timing model matches the RTL back end: transparent (blends)", "[timing]") {
  check_trace("traces/transparent.trace");
}
TEST_CASE("timing model matches the RTL back end: slivers", "[timing]") { check_trace("traces/sliver_fan.trace"); }
TEST_CASE("timing model matches the RTL back end: demo", "[timing]") { check_trace("traces/demo.trace"); }
TEST_CASE("timing model matches the RTL back end with write-behind and dirty bits: 200-pixel triangles", "[timing]") {
  check_memory_options("traces/equilateral_200.trace");
}
TEST_CASE("timing model matches the RTL back end with write-behind and dirty bits: z_overlap (Z rejections)",
          "[timing]") {
  check_memory_options("traces/z_overlap.trace");
}
TEST_CASE("timing model matches the RTL back end with write-behind and dirty bits: transparent", "[timing]") {
  check_memory_options("traces/transparent.trace");
}
TEST_CASE("timing model matches the RTL back end with write-behind and dirty bits: demo", "[timing]") {
  check_memory_options("traces/demo.trace");
}

}  // namespace girtd
