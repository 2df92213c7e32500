// accuracy.html: the accuracy run's page (opens offline): modeled-time
// error against wall time per row on log-log axes, a series per level
// (hover a point for its input, level and variant), and the level table.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "report/page_parts.hpp"

namespace girtd {

// `rows` and `levels`: accuracy.json's.
std::string accuracy_html(const std::string& command, const nlohmann::json& rows, const nlohmann::json& levels,
                          const std::optional<ChartLibrary>& charts);

}  // namespace girtd
