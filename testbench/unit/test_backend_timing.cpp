// The approx back end's timing model (sim/dda, sim/had) against the RTL back end
// (hw/backend) on the sample traces: the same page misses, DDA waits and
// tick count, the same FIFO occupancy over time and the same heat maps.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "rtl/timing_comparison.hpp"

namespace girtd {
namespace {

double max_of(const FifoSeries& s) {
  double m = 0;
  for (const auto& bin : s.bins()) m = std::max(m, bin[0]);
  return m;
}

// Entries that differ (a count: Catch2 would print whole screens).
template <typename T>
size_t differing(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
  return n;
}

void check_trace(const std::string& path, const Params& p = Params::defaults()) {
  const TimingComparison c = compare_timing(p, path);
  INFO(path << ": approx " << c.model.ticks << " ticks, RTL " << c.rtl.ticks << "; misses " << c.model.page_misses
            << " / " << c.rtl.page_misses << "; DDA wait ticks " << c.model.dda_wait_ticks << " / "
            << c.rtl.dda_wait_ticks);
  CHECK(c.model.page_misses == c.rtl.page_misses);
  CHECK(c.model.pixels_generated == c.rtl.pixels_generated);
  CHECK(c.model.dda_wait_ticks == c.rtl.dda_wait_ticks);
  CHECK(c.model.ticks == c.rtl.ticks);
  CHECK(c.model.had_busy_ticks == c.rtl.had_busy_ticks);
  CHECK(c.model.had_vram_wait_ticks == c.rtl.had_vram_wait_ticks);
  CHECK(c.model.fifo_max == c.rtl.fifo_max);
  // report.html's occupancy chart of the DDA -> HAD FIFO: the same bins, the same peaks.
  REQUIRE(c.model_fifo);
  REQUIRE(c.rtl_fifo);
  CHECK(c.model_fifo->bin_s() == c.rtl_fifo->bin_s());
  CHECK(c.model_fifo->bins() == c.rtl_fifo->bins());
  CHECK(double(c.rtl.fifo_max) == max_of(*c.rtl_fifo));
  // report.html's heat maps: the RTL's pushes and counters draw the golden DDA's maps,
  // and the misses per page add up to the RTL's own page-miss counter.
  REQUIRE(c.model_maps);
  REQUIRE(c.rtl_maps);
  CHECK(differing(c.rtl_maps->page_misses, c.model_maps->page_misses) == 0);
  CHECK(differing(c.rtl_maps->dda_waste, c.model_maps->dda_waste) == 0);
  uint64_t misses = 0;
  for (uint32_t m : c.rtl_maps->page_misses) misses += m;
  CHECK(misses == c.rtl.page_misses);
}

// The memory-side options, alone and together (run-time inputs of the
// built RTL). With prefetch, stolen cycles or a write-behind write under
// way the memory side is stepped tick by tick (sim/had/
// memory_side_ticks), else mostly pixel by pixel; a steal every 1 us (200 ticks) lands in
// every state of the HAD, the frame clear and the flush.
nlohmann::json options(const char* text) { return nlohmann::json::parse(text); }
const std::vector<const char*> kEveryOption = {
    R"({"had": {"write_behind": true}})",
    R"({"had": {"dirty_bits": true}})",
    R"({"had": {"write_behind": true, "dirty_bits": true}})",
    R"({"had": {"prefetch": true}})",
    R"({"had": {"prefetch": true, "write_behind": true}})",
    R"({"had": {"prefetch": true, "dirty_bits": true}})",
    R"({"vram": {"steal_every_ns": 1000.0}})",
    R"({"had": {"write_behind": true, "prefetch": true, "dirty_bits": true}, "vram": {"steal_every_ns": 700.0}})"};

void check_memory_options(const std::string& path, const std::vector<const char*>& list = kEveryOption) {
  for (const char* o : list) {
    INFO(o);
    check_trace(path, Params::with_overrides(options(o), "test"));
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
TEST_CASE("timing model matches the RTL back end with every memory-side option: 200-pixel triangles", "[timing]") {
  check_memory_options("traces/equilateral_200.trace");
}
TEST_CASE("timing model matches the RTL back end with every memory-side option: z_overlap (Z rejections)",
          "[timing]") {
  check_memory_options("traces/z_overlap.trace");
}
TEST_CASE("timing model matches the RTL back end with every memory-side option: transparent", "[timing]") {
  check_memory_options("traces/transparent.trace");
}
TEST_CASE("timing model matches the RTL back end with every memory-side option: demo", "[timing]") {
  check_memory_options("traces/demo.trace", {kEveryOption[2], kEveryOption[3], kEveryOption.back()});
}

}  // namespace girtd
