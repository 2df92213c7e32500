// The levels `girtd accuracy` runs: back ends and cheaper timing
// estimators, each a `girtd render` in its own process. A level says how
// it is rendered and which modeled time it stands for.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "backends/backend_entry.hpp"

namespace girtd {

struct AccuracyLevel {
  std::string name;     // rtl, approx, golden, reference, dda_bound, approx_sampled_<rate>
  std::string backend;  // the render's back end
  std::vector<std::string> render_args;
  bool draws_frame = true;  // false: the frame is incomplete (sampled timing), no picture error
  bool picture_yardstick = false;  // the back end pictures are judged against (kExactPicture)
  bool timing_yardstick = false;   // the back end modeled time is judged against (kExactTiming)
  bool estimator = false;  // a cheaper timing estimate made from a back end, not a back end itself
  std::string what;        // one line for the tables: the registry's summary, or how it estimates
  std::string modeled_time_key;  // the report.json key holding the modeled time it stands for
};

// What accuracy.json says of each level it ran (its "level_kinds"): the
// tables and tools/accuracy_*.py read these, never the level's name.
nlohmann::json level_kind(const AccuracyLevel& level);

// A back end's name, dda_bound (the untimed back end with a DDA: its clocks
// times the period) or approx_sampled_<rate> (the back end that samples
// timing); `backends`: the registry. Throws InputError("--backends", ...)
// for an unknown name.
AccuracyLevel accuracy_level(const std::string& name, const std::vector<BackendEntry>& backends);
// Every name accuracy_level() takes, for help and errors ("<rate>" for the rate).
std::string accuracy_level_names(const std::vector<BackendEntry>& backends);
// The default list: the timed back ends (the timing yardstick first),
// dda_bound and the sampling back end at 1/10 and 1/50.
std::vector<std::string> default_accuracy_levels(const std::vector<BackendEntry>& backends);

// The level's modeled time from its report.json: modeled_time_s for the
// timed back ends (estimates included), the DDA-bound time (clocks x
// period, no memory side) for dda_bound; none for golden and reference.
std::optional<double> level_modeled_time(const AccuracyLevel& level, const nlohmann::json& report);

}  // namespace girtd
