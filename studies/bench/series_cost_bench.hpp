// What report.html's series cost (`girtd bench`): the stage timelines, the
// heat maps and the FIFOs' occupancy, recorded on every timed run. Each
// input renders on approx and rtl with them and without (GIRTD_NO_SERIES,
// timeline/series_switch.hpp) in pairs, one after the other, each in its own
// process: the median over the pairs of the ratio of their `wall_s` (the
// simulation, where the series are recorded) and of their whole process
// (writing the page included).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "cli/config_loader.hpp"

namespace girtd {

struct SeriesCostBench {
  std::string markdown;
  nlohmann::json rows = nlohmann::json::array();
  int failures = 0;  // a render failed, or the two differ in anything but wall time
};

SeriesCostBench run_series_cost_bench(const ConfigFiles& config, const std::string& out_dir);

}  // namespace girtd
