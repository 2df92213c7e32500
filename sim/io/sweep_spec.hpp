// A sweep specification (docs/interface.md `girtd sweep`): inputs, back end, base
// configuration files, frames per input, rtl spot checks, and the axes. An
// axis named by a dotted configuration key takes values of that key; an
// axis whose values are objects sets several keys together. Axes are kept
// in name order (the last varies fastest). `repeat` draws each one-frame
// input that many times (sustained rates); an animation runs as it is.
// Every error is
// `SPEC:LINE: what`. (A parser a user reaches: the fuzz build has it.)
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace girtd {

struct SweepAxis {
  std::string name;
  std::vector<nlohmann::json> values;  // scalars (the key's values) or objects {dotted key: value}
  // The settings of one value: {name: value} or the object itself.
  nlohmann::json settings(size_t i) const;
};

// What a row takes from its render's report.json: its column name and where
// the report keeps it (a JSON pointer).
struct ReportColumn {
  const char* name;
  const char* pointer;
};
inline constexpr ReportColumn kReportColumns[] = {
    {"modeled_mpixels_per_s", "/modeled_mpixels_per_s"},
    {"sustained_mpixels_per_s", "/sustained_mpixels_per_s"},
    {"modeled_time_s", "/modeled_time_s"},
    {"target_met", "/target_met"},
    {"bottleneck", "/bottleneck"},
    {"had_busy_s", "/stages/had/busy_s"},
    {"had_page_wait_s", "/time_split/had_page_wait_s"},
    {"cache_accesses", "/cache/accesses"},
    {"page_misses", "/cache/page_misses"},
    {"image_sha256", "/image_sha256"},
    {"wall_s", "/wall_s"}};

struct SweepSpec {
  std::string path;
  std::vector<std::string> inputs;    // resolved against the spec's folder
  std::string backend = "approx";
  std::vector<std::string> base;      // configuration files, resolved
  int repeat = 1;
  int spot_check = 0;
  std::vector<SweepAxis> axes;
  size_t point_count() const;
};

// `timed_backends`: the back ends a sweep may name (it judges modeled time;
// the registry's timed entries).
SweepSpec parse_sweep_spec(const std::string& text, const std::string& path,
                           const std::vector<std::string>& timed_backends);
SweepSpec read_sweep_spec(const std::string& path, const std::vector<std::string>& timed_backends);

}  // namespace girtd
