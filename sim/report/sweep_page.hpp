// sweep.html: a sweep's page (opens offline): the headline, rate on the
// slowest input against cost for every valid point with the Pareto front
// and the target line (hover a point to read its configuration), and the
// front as a table.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/page_parts.hpp"

namespace girtd {

// `points`: summarize_sweep's per-point summary (sweep/sweep_table.hpp).
std::string sweep_html(const std::string& spec, const std::string& headline, const nlohmann::json& points,
                       const std::vector<std::string>& axes, double target_mpixels_per_s,
                       const std::optional<ChartLibrary>& charts);

}  // namespace girtd
