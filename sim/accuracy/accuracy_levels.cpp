#include "accuracy/accuracy_levels.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "common/input_error.hpp"

namespace girtd {

namespace {

constexpr const char* kSampledPrefix = "approx_sampled_";

// The first back end whose capabilities include `has` and exclude `lacks`.
const BackendEntry& first_with(const std::vector<BackendEntry>& backends, unsigned has, unsigned lacks) {
  for (const BackendEntry& b : backends)
    if ((b.capabilities & has) == has && !(b.capabilities & lacks)) return b;
  throw std::logic_error("the back-end registry has no entry for an accuracy level");
}

}  // namespace

AccuracyLevel accuracy_level(const std::string& name, const std::vector<BackendEntry>& backends) {
  for (const BackendEntry& b : backends)
    if (b.name == name) return {name, name, {}, true, b.has(kExactPicture), b.has(kExactTiming), false, b.summary};
  if (name == "dda_bound") {
    const std::string untimed = first_with(backends, kDrawsWithDda, kModelsTime).name;
    return {name, untimed, {}, true, false, false, true,
            untimed + "'s DDA clocks x the DDA period (no front end, no memory side)"};
  }
  if (name.rfind(kSampledPrefix, 0) == 0) {
    const std::string rate = name.substr(std::string(kSampledPrefix).size());
    char* end = nullptr;
    const double r = std::strtod(rate.c_str(), &end);
    if (!rate.empty() && *end == '\0' && r > 0 && r < 1) {
      const std::string sampler = first_with(backends, kSamplesTiming, 0).name;
      char what[160];
      std::snprintf(what, sizeof what, "%s timing 1 triangle in %g, the rest skipped (SMARTS-style, ratio estimator)",
                    sampler.c_str(), 1 / r);
      return {name, sampler, {"--sample-timing", rate}, false, false, false, true, what};
    }
    throw InputError("--backends", 0, "'" + name + "': the sampling rate must be a number in (0, 1), e.g. approx_sampled_0.1");
  }
  throw InputError("--backends", 0,
                   "'" + name + "': not a level (rtl, approx, golden, reference, dda_bound, approx_sampled_<rate>)");
}

nlohmann::json level_kind(const AccuracyLevel& level) {
  return {{"level", level.name},
          {"backend", level.backend},
          {"what", level.what},
          {"estimator", level.estimator},
          {"complete", level.draws_frame},
          {"picture_yardstick", level.picture_yardstick},
          {"timing_yardstick", level.timing_yardstick}};
}

std::vector<std::string> default_accuracy_levels() {
  return {"rtl", "approx", "dda_bound", "approx_sampled_0.1", "approx_sampled_0.02"};
}

std::optional<double> level_modeled_time(const AccuracyLevel& level, const nlohmann::json& report) {
  const char* key = level.name == "dda_bound" ? "dda_bound_time_s" : "modeled_time_s";
  if (!report.contains(key) || report[key].is_null()) return std::nullopt;
  return report[key].get<double>();
}

}  // namespace girtd
