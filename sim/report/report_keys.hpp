// The registry of report.json's keys: each key is declared once here, with
// its unit, its meaning, which back ends know it and how its value is read
// from a run. report.json, report.md's key table, `not_modeled` and the key
// table in sim/README.md (girtd_report_keys) all come from it.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "backends/backend_entry.hpp"
#include "backends/prune_plan.hpp"
#include "backends/run_stats.hpp"
#include "config/params.hpp"

namespace girtd {

// What a render knows besides its RunStats.
struct ReportContext {
  std::string backend;
  unsigned capabilities = 0;  // the back end's (backends/backend_entry.hpp)
  std::string input;
  std::string level;
  std::string image_sha256;
  std::vector<std::string> warnings;  // input the run went on from ("FILE: what")
  std::string rtl_build;              // the rtl back end's RTL build key; "" for the others
  uint64_t front_end_passes = 0;      // runs of the front end over the input (backends/front_end_runner.hpp)
  std::vector<LeftOut> left_out;      // what the simulator skipped (backends/prune_plan.hpp)
};

struct ReportSource {
  const ReportContext& ctx;
  const RunStats& s;
  const Params& params;
};

// Which back ends can know a key: the capabilities it needs of one
// (backends/backend_entry.hpp). The others report it as null and list it in
// not_modeled.
enum KnownBy : unsigned {
  kEvery = 0,
  kHardware = kDrawsWithDda,  // the back ends that run the DDA
  kTimed = kModelsTime,
  kSurfaces = kSeesSurfaces,
  kSampled = kSamplesTiming,
};

struct ReportKey {
  std::string path;  // dotted; "stages.*.busy_s" for a key of every stage
  std::string unit;
  std::string meaning;
  unsigned known_by = kEvery;  // the capabilities a back end needs to know it
  bool known_to(unsigned capabilities) const { return (capabilities & known_by) == known_by; }
  bool summary = false;  // a row of report.md's key table
  // The value (null when this input has none, e.g. no front end ran); a
  // key of every stage reads the stage instead.
  std::function<nlohmann::json(const ReportSource&)> value;
  std::function<nlohmann::json(const ReportSource&, const StageStats&)> stage_value;
};

// Every key, in report order.
const std::vector<ReportKey>& report_keys();

// The registered keys a back end with these capabilities cannot know.
std::vector<std::string> not_modeled_keys(unsigned capabilities);

// sim/README.md's key table (girtd_report_keys prints it), naming which of
// `backends` know each key.
std::string report_keys_markdown(const std::vector<BackendEntry>& backends);

}  // namespace girtd
