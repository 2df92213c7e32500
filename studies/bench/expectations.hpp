// Stored expectations (testbench/golden/expectations.json): per sample
// workload, the picture's SHA-256, the triangle and pixel counts, DDA clocks
// per state, page misses and modeled base ticks the design as blessed
// produces. `bench --pipeline` compares every back end's report with them;
// `bench --pipeline --bless` (tools/girtd bless) rewrites them after an
// intended change and prints what changed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/params.hpp"

namespace girtd {

constexpr const char* kExpectationFile = "testbench/golden/expectations.json";

// The fields of a report that are stored; a back end's `null` (golden's
// modeled time) stays null and is not compared.
nlohmann::json expectation_of(const nlohmann::json& report, const Params& params);

// "key: expected X, got Y" for every stored field `got` has and differs in.
std::vector<std::string> expectation_differences(const nlohmann::json& expected, const nlohmann::json& got);

// The stored file; nullopt when there is none.
struct StoredExpectations {
  std::string config_key;
  nlohmann::json inputs;  // input path -> expectation_of(...)
};
std::optional<StoredExpectations> load_expectations();

// What blessing `inputs` under `key` changes against `old`: one line per
// changed value, added or dropped input, or the configuration.
std::vector<std::string> bless_changes(const std::optional<StoredExpectations>& old, const nlohmann::json& inputs,
                                       const std::string& key);

// Writes the file whole or not at all.
void save_expectations(const nlohmann::json& inputs, const std::string& key);

}  // namespace girtd
