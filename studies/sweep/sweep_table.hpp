// A sweep's tables: per point (the rate it sustains on its worst input,
// whether it meets the target on every input, its cost), the Pareto front
// of rate against cost, the cheapest point that meets the target, and the
// rows as CSV.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/sweep_spec.hpp"

namespace girtd {

struct SweepSummary {
  nlohmann::json points;  // one per point: point, axis values, valid, cost, min_mpixels_per_s, meets_target, on_front
  std::string markdown;
  std::string headline;   // a few lines for the terminal
};

// The rate a row is judged by: sustained when the input ran as several
// frames, else over the whole run.
double judged_rate(const nlohmann::json& row);

// Sets each point's on_front: valid, and no other valid point is at once
// no dearer and no slower (min_mpixels_per_s), and better in one. The one
// definition of the front: a sweep's tables and the campaign's
// (girtd_campaign_front, studies/study_summary.py) both use it.
void mark_pareto_front(nlohmann::json& points);

SweepSummary summarize_sweep(const nlohmann::json& rows, const std::vector<std::string>& axes, size_t inputs);
std::string sweep_csv(const nlohmann::json& rows, const std::vector<std::string>& axes);

}  // namespace girtd
