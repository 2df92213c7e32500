// Chapter 5's campaign claims (studies/claims/campaign_claims) on a hand-made
// results file: two inputs with worked numbers, and the file missing.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "claims/campaign_claims.hpp"

namespace girtd {
namespace {

nlohmann::json row(const char* input, bool wb, bool pf, double wait_s, double busy_s, double accesses, double rate) {
  return {{"input", input}, {"valid", true}, {"dda.clock_ns", 35.0}, {"had.access_ns", 25.0}, {"cache.pages", 1},
          {"pipeline.flops_per_s.lighting", 1e7}, {"memory", {{"had.write_behind", wb}, {"had.prefetch", pf}}},
          {"had_page_wait_s", wait_s}, {"had_busy_s", busy_s}, {"cache_accesses", accesses},
          {"sustained_mpixels_per_s", rate}, {"modeled_mpixels_per_s", rate}};
}

}  // namespace

TEST_CASE("campaign claims from stored results, worked by hand", "[claims]") {
  // a: waits 0.4 s -> 0.2 s with write-behind (0.5); b: 0.3 -> 0.18 (0.6): median 0.55, refuted (> 5 % off 0.5).
  // With both: a waits 0.003 s for 1e6 pixels (3 ns each, 10 % of 0.030 s), b 0.0028 s for 2e6 (1.4 ns, 5 % of
  // 0.056 s): median 2.2 ns, under a base tick: confirmed. Rates 19 and 21: median 20 against ~40: refuted.
  nlohmann::json doc = {{"rows", nlohmann::json::array()}};
  for (const nlohmann::json& r :
       {row("a", false, false, 0.4, 1.0, 1e6, 9), row("a", true, false, 0.2, 0.8, 1e6, 12),
        row("a", true, true, 0.003, 0.030, 1e6, 19), row("b", false, false, 0.3, 1.0, 2e6, 10),
        row("b", true, false, 0.18, 0.9, 2e6, 11), row("b", true, true, 0.0028, 0.056, 2e6, 21)})
    doc["rows"].push_back(r);
  const std::string path = "/tmp/girtd_test_campaign_claims.json";
  std::ofstream(path) << doc.dump();
  const std::vector<ClaimRow> rows = campaign_claims(path);
  std::remove(path.c_str());
  REQUIRE(rows.size() == 3);
  CHECK(rows[0].measured.find("median 0.55 (0.50 to 0.60) over 2 inputs") != std::string::npos);
  CHECK(rows[0].verdict == "refuted");
  CHECK(rows[1].measured.find("median 2.2 ns per pixel (1.4 to 3.0)") != std::string::npos);
  CHECK(rows[1].measured.find("8 % of the HAD's time (5 % to 10 %)") != std::string::npos);
  CHECK(rows[1].verdict == "confirmed");
  CHECK(rows[2].measured.find("median 20.0 Mpixel/s (19.0 to 21.0)") != std::string::npos);
  CHECK(rows[2].verdict == "refuted");
}

TEST_CASE("campaign claims without stored results are not yet measured", "[claims]") {
  for (const ClaimRow& r : campaign_claims("/nonexistent/results.json")) CHECK(r.verdict == "not yet measured");
}

}  // namespace girtd
