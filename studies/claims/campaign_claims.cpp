#include "claims/campaign_claims.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "config/params.hpp"
#include "io/text_format.hpp"

namespace girtd {
using json = nlohmann::json;

namespace {

struct Spread {
  double median = 0, min = 0, max = 0;
};
Spread spread(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return {n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]), v.front(), v.back()};
}

// The rows of the thesis' timings (config/girtd.json's defaults: the DDA
// clock, the HAD's access, its cache, the lighting rate) with the given
// memory side, by input.
std::map<std::string, json> rows_with(const json& doc, bool write_behind, bool prefetch) {
  static const Params thesis = Params::defaults();
  std::map<std::string, json> out;
  for (const json& r : doc.at("rows")) {
    if (!r.value("valid", false) || r.at("dda.clock_ns") != thesis.dda_clock_ns ||
        r.at("had.access_ns") != thesis.had_access_ns || r.at("cache.pages") != thesis.cache_pages ||
        r.at("pipeline.flops_per_s.lighting") != thesis.stage_rate_flops_per_s.at("lighting"))
      continue;
    const json& m = r.at("memory");
    if (m.at("had.write_behind") == write_behind && m.at("had.prefetch") == prefetch) out[r.at("input")] = r;
  }
  return out;
}

double rate(const json& r) {
  return r.at("sustained_mpixels_per_s").is_null() ? r.at("modeled_mpixels_per_s").get<double>()
                                                   : r.at("sustained_mpixels_per_s").get<double>();
}

}  // namespace

std::vector<ClaimRow> campaign_claims(const std::string& results_path) {
  const std::string wb_claim = "write-behind halves VRAM time (5.2.2), the study's inputs";
  const std::string pf_claim = "prefetch + write-behind: ~100 % cache hits (5.2.2), the study's inputs";
  const std::string rate_claim = "~40 Mpixel/s with write-behind and prefetch (5.2.2), the study's inputs";
  const std::string wb_thesis = "HAD's VRAM wait with write-behind / without = 0.5";
  const std::string pf_thesis = "every access a hit: no time waiting for pages";
  const std::string rate_thesis = "~40 Mpixel/s";
  auto not_measured = [&](const std::string& why) {
    const std::string none = "not yet measured (" + results_path + ": " + why + ")";
    return std::vector<ClaimRow>{{wb_claim, wb_thesis, none, "not yet measured"},
                                 {pf_claim, pf_thesis, none, "not yet measured"},
                                 {rate_claim, rate_thesis, none, "not yet measured"}};
  };
  std::ifstream in(results_path);
  if (!in) return not_measured("run the study's sweeps");
  const json doc = json::parse(in);
  const auto plain = rows_with(doc, false, false), wb = rows_with(doc, true, false), pf = rows_with(doc, true, true);
  std::vector<double> wait_ratio, wait_ns, wait_share, rates;
  for (const auto& [input, r] : plain) {
    if (!wb.count(input) || !pf.count(input) || !(r.at("had_page_wait_s").get<double>() > 0)) continue;
    wait_ratio.push_back(wb.at(input).at("had_page_wait_s").get<double>() / r.at("had_page_wait_s").get<double>());
    const json& p = pf.at(input);
    wait_ns.push_back(1e9 * p.at("had_page_wait_s").get<double>() / p.at("cache_accesses").get<double>());
    wait_share.push_back(p.at("had_page_wait_s").get<double>() / p.at("had_busy_s").get<double>());
    rates.push_back(rate(p));
  }
  if (wait_ratio.empty()) return not_measured("no thesis-timing rows for all three memory sides");
  const size_t n = wait_ratio.size();
  const Spread w = spread(wait_ratio), ns = spread(wait_ns), share = spread(wait_share), r = spread(rates);
  std::vector<ClaimRow> rows;
  rows.push_back({wb_claim, wb_thesis,
                  format_numbers("median %.2f (%.2f to %.2f) over ", w.median, w.min, w.max) + std::to_string(n) + " inputs",
                  std::fabs(w.median - 0.5) <= 0.05 * 0.5 ? "confirmed" : "refuted"});
  // A page wait under one base tick per pixel counts as every access a hit.
  static const Params thesis = Params::defaults();
  rows.push_back({pf_claim, pf_thesis,
                  format_numbers("waiting for pages: median %.1f ns per pixel (%.1f to %.1f); ", ns.median, ns.min, ns.max) +
                      format_numbers("%.0f %% of the HAD's time (%.0f %% to %.0f %%)", 100 * share.median, 100 * share.min,
                          100 * share.max),
                  ns.median <= thesis.base_tick_ns ? "confirmed" : "refuted"});
  rows.push_back({rate_claim, rate_thesis,
                  format_numbers("median %.1f Mpixel/s (%.1f to %.1f), sustained; the DDA clocks at %.0f ns", r.median, r.min,
                      r.max, thesis.dda_clock_ns),
                  std::fabs(r.median - 40.0) <= 0.05 * 40.0 ? "confirmed" : "refuted"});
  return rows;
}

}  // namespace girtd
