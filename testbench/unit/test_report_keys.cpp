// The report key registry (sim/report/report_keys.cpp) against the
// contract's list (docs/interface.md, copied here by hand) and its own
// rules: every key once, summary keys at the top level, a registered back
// end's not_modeled exactly the keys it cannot know.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include "engine/backend_registry.hpp"
#include "report/report.hpp"

namespace girtd {

TEST_CASE("the registry declares every key the contract names, each once", "[report]") {
  std::set<std::string> paths;
  for (const ReportKey& k : report_keys()) {
    CHECK(paths.insert(k.path).second);  // declared once
    CHECK(!k.unit.empty());
    CHECK(!k.meaning.empty());
    CHECK(bool(k.value) != bool(k.stage_value));  // read from the run or from a stage, not both
    if (k.summary) CHECK(k.path.find('.') == std::string::npos);
  }
  for (const char* contract :
       {"backend", "input", "triangles_in", "triangles_drawn", "pixels_generated", "pixels_written", "pixels_blended",
        "pixels_z_rejected", "pixels_dropped", "dda_cycles", "dda_efficiency", "clock_ns", "modeled_time_s",
        "modeled_mpixels_per_s", "target_mpixels_per_s", "bottleneck", "cache.accesses", "cache.page_misses",
        "cache.nac", "stages.*.items", "stages.*.busy_s", "stages.*.stall_s", "wall_s", "image_sha256", "not_modeled",
        "warnings"})
    CHECK(paths.count(contract) == 1);
}

TEST_CASE("not_modeled: nothing on approx, seams and sampling on rtl, the timing keys on golden, the DDA's too on "
          "reference",
          "[report]") {
  CHECK(not_modeled(backend_named("approx")).empty());
  // The RTL counts wraps too (hw/dda/dda_limits.sv); its HAD sees no surface
  // ids; sampled timing is approx's estimator.
  CHECK(not_modeled(backend_named("rtl")) == std::vector<std::string>{"pixels_reblended", "sampling"});
  const std::vector<std::string> golden = not_modeled(backend_named("golden")),
                                 reference = not_modeled(backend_named("reference"));
  auto has = [](const std::vector<std::string>& v, const char* k) { return std::count(v.begin(), v.end(), k) == 1; };
  for (const char* k : {"modeled_time_s", "bottleneck", "cache.page_misses", "stages.*.busy_s", "target_met",
                        "sustained_mpixels_per_s", "sampling"}) {
    CHECK(has(golden, k));
    CHECK(has(reference, k));
  }
  CHECK(!has(golden, "dda_cycles"));
  CHECK(has(reference, "dda_cycles"));
  CHECK(!has(golden, "pixels_written"));
}

TEST_CASE("a golden report: registered keys present, unknown ones null, groups of a null group left out", "[report]") {
  RunStats s;
  s.frames = 1;
  s.pixels_generated = 10;
  s.had.written = 10;
  s.dda = DdaRunStats{};
  s.dda->cycles = 20;
  s.dda->emitted = 10;
  s.stages.push_back(untimed_stage("dda", 1));
  ReportContext ctx;
  ctx.backend = "golden";
  ctx.capabilities = backend_named("golden").capabilities;
  const Params p = Params::defaults();
  const nlohmann::json r = make_report(ctx, s, p);
  CHECK(r.at("dda_efficiency") == 0.5);  // 10 emitting clocks of 20
  CHECK(r.at("modeled_time_s").is_null());
  CHECK(r.at("cache").at("page_misses").is_null());
  CHECK(r.at("stages").at("dda").at("items") == 1);
  CHECK(r.at("stages").at("dda").at("busy_s").is_null());
  CHECK(r.at("frontend").is_null());  // no front end ran: the group is null, its keys left out
  CHECK(r.at("preparer").is_null());
  CHECK(report_markdown(r).find("| `dda_efficiency` | 0.5 |") != std::string::npos);
}

}  // namespace girtd
