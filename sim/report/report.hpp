// report.json and report.md, both from the key registry (report_keys.hpp).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "report/report_keys.hpp"

namespace girtd {

// Every registered key, null where this back end cannot know it or this
// input has no value; a key of a null group (`frontend` below the front
// end) is left out with it.
nlohmann::json make_report(const ReportContext& ctx, const RunStats& s, const Params& params);
std::string report_markdown(const nlohmann::json& report);

}  // namespace girtd
