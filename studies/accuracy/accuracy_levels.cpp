#include "accuracy/accuracy_levels.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "common/input_error.hpp"

namespace girtd {

namespace {

constexpr const char* kDdaBound = "dda_bound";

// The first back end whose capabilities include `has` and exclude `lacks`.
const BackendEntry& first_with(const std::vector<BackendEntry>& backends, unsigned has, unsigned lacks) {
  for (const BackendEntry& b : backends)
    if ((b.capabilities & has) == has && !(b.capabilities & lacks)) return b;
  throw std::logic_error("the back-end registry has no entry for an accuracy level");
}

// The sampled levels are named after the back end that samples timing.
std::string sampled_prefix(const std::vector<BackendEntry>& backends) {
  return first_with(backends, kSamplesTiming, 0).name + "_sampled_";
}

}  // namespace

std::string accuracy_level_names(const std::vector<BackendEntry>& backends) {
  std::string out;
  for (const BackendEntry& b : backends) out += b.name + ", ";
  return out + kDdaBound + ", " + sampled_prefix(backends) + "<rate>";
}

AccuracyLevel accuracy_level(const std::string& name, const std::vector<BackendEntry>& backends) {
  for (const BackendEntry& b : backends)
    if (b.name == name)
      return {name, name, {}, true, b.has(kExactPicture), b.has(kExactTiming), false, b.summary, "modeled_time_s"};
  if (name == kDdaBound) {
    const std::string untimed = first_with(backends, kDrawsWithDda, kModelsTime).name;
    return {name, untimed, {}, true, false, false, true,
            untimed + "'s DDA clocks x the DDA period (no front end, no memory side)", "dda_bound_time_s"};
  }
  const std::string prefix = sampled_prefix(backends);
  if (name.rfind(prefix, 0) == 0) {
    const std::string rate = name.substr(prefix.size());
    char* end = nullptr;
    const double r = std::strtod(rate.c_str(), &end);
    if (!rate.empty() && *end == '\0' && r > 0 && r < 1) {
      const std::string sampler = first_with(backends, kSamplesTiming, 0).name;
      char what[160];
      std::snprintf(what, sizeof what, "%s timing 1 triangle in %g, the rest skipped (SMARTS-style, ratio estimator)",
                    sampler.c_str(), 1 / r);
      return {name, sampler, {"--sample-timing", rate}, false, false, false, true, what, "modeled_time_s"};
    }
    throw InputError("--backends", 0, "'" + name + "': the sampling rate must be a number in (0, 1), e.g. " + prefix + "0.1");
  }
  throw InputError("--backends", 0, "'" + name + "': not a level (" + accuracy_level_names(backends) + ")");
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

std::vector<std::string> default_accuracy_levels(const std::vector<BackendEntry>& backends) {
  std::vector<std::string> out;
  for (const BackendEntry& b : backends)  // the timing yardstick first, then the other timed back ends
    if (b.has(kExactTiming)) out.push_back(b.name);
  for (const BackendEntry& b : backends)
    if (b.has(kModelsTime) && !b.has(kExactTiming)) out.push_back(b.name);
  out.push_back(kDdaBound);
  for (const char* rate : {"0.1", "0.02"}) out.push_back(sampled_prefix(backends) + rate);
  return out;
}

std::optional<double> level_modeled_time(const AccuracyLevel& level, const nlohmann::json& report) {
  const std::string& key = level.modeled_time_key;
  if (!report.contains(key) || report[key].is_null()) return std::nullopt;
  return report[key].get<double>();
}

}  // namespace girtd
