#include "cli/expectations.hpp"

#include <cmath>

#include "io/sha256.hpp"

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

std::string config_key(const Params& params) {
  const std::string text = params.source.dump();
  return sha256_hex(std::vector<uint8_t>(text.begin(), text.end())).substr(0, 16);
}

}  // namespace girtd
