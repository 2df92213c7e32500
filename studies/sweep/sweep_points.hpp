// The points of a sweep: every combination of the axes' values, each a
// configuration merged over the spec's base files, named by a hash of the
// merged configuration (so the same design has the same name in every
// spec, run and machine). A point the configuration refuses, or the back
// end cannot run, is invalid, with the reason.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/sweep_spec.hpp"

namespace girtd {

struct SweepPoint {
  std::string id;              // 16 hex digits
  nlohmann::json axis_values;  // {axis name: value}
  nlohmann::json settings;     // {dotted key: value}
  std::string config_file;     // the override, written under DIR/points/
  std::string invalid;         // why it cannot run ("" when valid)
  nlohmann::json cost;         // models/cost/hardware_cost.hpp, as JSON (valid points)
};

// Writes each point's override file under `dir`/points/.
std::vector<SweepPoint> sweep_points(const SweepSpec& spec, const std::string& dir);

}  // namespace girtd
