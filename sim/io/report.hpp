// report.json and report.md (keys documented with units in sim/README.md).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "backends/run_stats.hpp"
#include "config/params.hpp"

namespace girtd {

struct ReportContext {
  std::string backend;
  std::string input;
  std::string level;
  std::vector<std::string> not_modeled;
  std::string image_sha256;
  std::vector<std::string> warnings;  // input the run went on from ("FILE: what")
  std::string rtl_build;              // the rtl back end's RTL build key; "" for the others
};

nlohmann::json make_report(const ReportContext& ctx, const RunStats& s, const Params& params);
std::string report_markdown(const nlohmann::json& report);

}  // namespace girtd
