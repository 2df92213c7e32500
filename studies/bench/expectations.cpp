#include "bench/expectations.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/output_set.hpp"
#include "common/input_error.hpp"

namespace girtd {

using nlohmann::json;

namespace {

json ticks(const json& seconds, double tick_ns) {
  if (seconds.is_null()) return nullptr;
  return std::llround(seconds.get<double>() / (tick_ns * 1e-9));
}

}  // namespace

json expectation_of(const json& r, const Params& params) {
  json e;
  for (const char* k : {"image_sha256", "triangles_in", "triangles_drawn", "pixels_generated", "pixels_written",
                        "pixels_blended", "pixels_z_rejected", "pixels_dropped", "dda_cycles"})
    e[k] = r.at(k);
  e["dda_states"] = r.value("dda_states", json());
  e["page_misses"] = r.at("cache").at("page_misses");
  e["modeled_ticks"] = ticks(r.at("modeled_time_s"), params.base_tick_ns);
  const json& had = r.at("stages").contains("had") ? r.at("stages").at("had") : json::object();
  e["had_busy_ticks"] = ticks(had.value("busy_s", json()), params.base_tick_ns);
  return e;
}

std::vector<std::string> expectation_differences(const json& expected, const json& got) {
  std::vector<std::string> out;
  for (auto it = expected.begin(); it != expected.end(); ++it) {
    const json g = got.value(it.key(), json());
    if (g.is_null() || it->is_null() || g == *it) continue;
    if (it->is_object() && g.is_object()) {
      for (const std::string& d : expectation_differences(*it, g)) out.push_back(it.key() + "." + d);
      continue;
    }
    out.push_back(it.key() + ": expected " + it->dump() + ", got " + g.dump());
  }
  return out;
}

std::optional<StoredExpectations> load_expectations() {
  std::ifstream in(kExpectationFile);
  if (!in) return std::nullopt;
  const json file = json::parse(in, nullptr, false);
  if (file.is_discarded() || !file.contains("config_key") || !file.contains("inputs"))
    throw InputError(kExpectationFile, 0, "not a stored-expectations file: re-bless it (tools/girtd bless)");
  return StoredExpectations{file.at("config_key").get<std::string>(), file.at("inputs")};
}

std::vector<std::string> bless_changes(const std::optional<StoredExpectations>& old, const json& inputs,
                                       const std::string& key) {
  if (!old) return {"no stored expectations before: " + std::to_string(inputs.size()) + " input(s) stored"};
  std::vector<std::string> out;
  if (old->config_key != key)
    out.push_back("configuration " + old->config_key + " -> " + key + ": every value re-blessed");
  for (auto it = inputs.begin(); it != inputs.end(); ++it) {
    if (!old->inputs.contains(it.key())) {
      out.push_back(it.key() + ": new");
      continue;
    }
    for (const std::string& d : expectation_differences(old->inputs.at(it.key()), *it)) out.push_back(it.key() + ": " + d);
  }
  for (auto it = old->inputs.begin(); it != old->inputs.end(); ++it)
    if (!inputs.contains(it.key())) out.push_back(it.key() + ": dropped");
  return out;
}

void save_expectations(const json& inputs, const std::string& key) {
  const std::filesystem::path path(kExpectationFile);
  const json file = {{"config_key", key},
                     {"about", "girtd bench --pipeline --bless (tools/girtd bless); testbench/README.md"},
                     {"inputs", inputs}};
  OutputSet out(path.parent_path().string());
  out.add_text(path.filename().string(), file.dump(1) + "\n");
  out.commit();
}

}  // namespace girtd
