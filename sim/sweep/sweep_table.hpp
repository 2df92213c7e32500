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

SweepSummary summarize_sweep(const nlohmann::json& rows, const std::vector<std::string>& axes, size_t inputs);
std::string sweep_csv(const nlohmann::json& rows, const std::vector<std::string>& axes);

}  // namespace girtd
