#include "report/report.hpp"

#include <algorithm>
#include <sstream>

#include "dda/dda_params.hpp"

namespace girtd {

using nlohmann::json;

namespace {

// The object a dotted path's last part goes in; nullptr when a group on the
// way is null (its keys are left out with it).
json* parent_of(json& r, const std::string& path, std::string& leaf) {
  json* at = &r;
  size_t from = 0;
  for (size_t dot; (dot = path.find('.', from)) != std::string::npos; from = dot + 1) {
    const std::string group = path.substr(from, dot - from);
    if (!at->contains(group)) (*at)[group] = json::object();
    at = &(*at)[group];
    if (at->is_null()) return nullptr;
  }
  leaf = path.substr(from);
  return at;
}

}  // namespace

json make_report(const ReportContext& ctx, const RunStats& s, const Params& params) {
  const ReportSource src{ctx, s, params};
  json r = json::object();
  json stages = json::object();
  for (const StageStats& st : s.stages) stages[st.name] = json::object();
  for (const ReportKey& k : report_keys()) {
    const bool known = k.known_to(ctx.capabilities);
    if (k.stage_value) {
      const std::string leaf = k.path.substr(k.path.rfind('.') + 1);
      for (const StageStats& st : s.stages) stages[st.name][leaf] = known ? k.stage_value(src, st) : json();
      continue;
    }
    std::string leaf;
    json* parent = parent_of(r, k.path, leaf);
    if (parent) (*parent)[leaf] = known ? k.value(src) : json();
  }
  r["stages"] = stages;
  return r;
}

namespace {

std::string num(const json& v, int precision = 4) {
  if (v.is_null()) return "—";
  if (v.is_string()) return v.get<std::string>();
  if (!v.is_number_float()) return v.dump();
  std::ostringstream f;
  f.precision(precision);
  f << v.get<double>();
  return f.str();
}

std::string throughput_markdown(const json& r) {
  std::ostringstream o;
  const bool sustained = !r.at("sustained_mpixels_per_s").is_null();
  const double rate = r.at(sustained ? "sustained_mpixels_per_s" : "modeled_mpixels_per_s"),
               target = r.at("target_mpixels_per_s");
  const double t = r.at("modeled_time_s");
  o << "\n## Throughput\n\n";
  o << (r.at("target_met").get<bool>() ? "PASS" : "FAIL") << ": " << (sustained ? "sustained " : "modeled ") << num(rate)
    << " Mpixel/s against the "
    << num(target) << " Mpixel/s target (" << num(r.at("back_end_mpixels_per_s")) << " Mpixel/s with the DDA fed; "
    << "bottleneck: " << r.at("bottleneck").get<std::string>() << ")\n\n";
  o << "| where the time went | s | share of " << num(t) << " s |\n|---|---|---|\n";
  for (auto it = r.at("time_split").begin(); it != r.at("time_split").end(); ++it)
    o << "| " << it.key() << " | " << num(*it) << " | " << num(it->get<double>() / t * 100, 3) << " % |\n";
  if (!r.at("preparer_triangles_per_s").is_null())
    o << "\nPreparer: delivered " << num(r.at("preparer_triangles_per_s")) << " triangles/s (can do "
      << num(r.at("preparer_capacity_triangles_per_s")) << "; the thesis asks for "
      << num(r.at("target_preparer_triangles_per_s")) << ")\n";
  return o.str();
}

std::string stages_markdown(const json& stages, const json& order) {
  std::ostringstream o;
  o << "| stage | items | busy_s | stall_s | starved_s | blocked_s | utilization | FIFO max in |\n"
    << "|---|---|---|---|---|---|---|---|\n";
  auto cell = [](const json& st, const char* k) { return num(st.at(k)); };
  for (const json& name : order) {
    const json* it = &stages.at(name.get<std::string>());
    o << "| " << name.get<std::string>() << " | " << it->at("items") << " | " << cell(*it, "busy_s") << " | " << cell(*it, "stall_s")
      << " | " << cell(*it, "starved_s") << " | " << cell(*it, "blocked_s") << " | " << cell(*it, "utilization")
      << " | " << cell(*it, "fifo_in_max") << " |\n";
  }
  return o.str();
}

}  // namespace

std::string report_markdown(const json& r) {
  std::ostringstream o;
  o << "# GIRTD render report\n\n";
  o << "| key | value |\n|---|---|\n";
  const json& unknown = r.at("not_modeled");
  for (const ReportKey& k : report_keys()) {
    if (!k.summary) continue;
    const bool not_modeled = std::find(unknown.begin(), unknown.end(), json(k.path)) != unknown.end();
    o << "| `" << k.path << "` | " << (not_modeled ? "not modeled" : num(r.at(k.path))) << " |\n";
  }
  const uint64_t gen = r.at("pixels_generated");
  const uint64_t sum = r.at("pixels_written").get<uint64_t>() + r.at("pixels_blended").get<uint64_t>() +
                       r.at("pixels_z_rejected").get<uint64_t>() + r.at("pixels_dropped").get<uint64_t>();
  o << "\nPixel accounting: generated " << gen << " = written + blended + z_rejected + dropped = " << sum
    << (gen == sum ? " (holds)" : " (BROKEN)") << "\n";
  if (!r.at("modeled_time_s").is_null()) o << throughput_markdown(r);
  if (r.at("frontend").is_object()) {
    o << "\nFront end (counts over all frames):\n\n| count | value |\n|---|---|\n";
    for (auto it = r.at("frontend").begin(); it != r.at("frontend").end(); ++it)
      o << "| `" << it.key() << "` | " << it->dump() << " |\n";
  }
  o << "\nStages:\n\n" << stages_markdown(r.at("stages"), r.at("stage_order"));
  if (r.at("numerics").is_object()) {  // where the EPs' formats were exceeded (dda/ep_numerics.hpp)
    o << "\nNumerics (triangles affected: " << r.at("numerics").at("triangles_affected") << "):\n\n"
      << "| EP | wrapped values in use | outputs clipped | preparer clamps |\n|---|---|---|---|\n";
    for (const char* ep : kEpNames) {
      const json& e = r.at("numerics").at(ep);
      o << "| " << ep << " | " << e.at("wraps") << " | " << e.at("saturations") << " | " << e.at("clamps") << " |\n";
    }
  }
  o << "\nWarnings: " << (r.at("warnings").empty() ? "none" : "") << "\n";
  for (const auto& w : r.at("warnings")) o << "\n- " << w.get<std::string>() << "\n";
  o << "\nLeft out by the simulator (nothing the outputs depend on; `--no-prune` turns it off): " << (r.at("left_out").empty() ? "nothing" : "")
    << "\n";
  for (const auto& l : r.at("left_out"))
    o << "\n- " << l.at("unit").get<std::string>() << ": " << l.at("reason").get<std::string>() << "\n";
  o << "\nNot modeled by this back end: " << (r.at("not_modeled").empty() ? "nothing" : "");
  for (const auto& k : r.at("not_modeled")) o << "`" << k.get<std::string>() << "` ";
  o << "\n";
  return o.str();
}

}  // namespace girtd
