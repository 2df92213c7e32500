#include "io/report.hpp"

#include <sstream>

#include "dda/dda_engine.hpp"

namespace girtd {

using nlohmann::json;

namespace {

template <typename T>
json opt(const std::optional<T>& v) {
  return v ? json(*v) : json(nullptr);
}

json stage_json(const StageStats& st, const std::optional<PipelineTiming>& t) {
  json j{{"items", st.items}, {"busy_s", opt(st.busy_s)}, {"stall_s", opt(st.stall_s)}};
  if (!t) return j;
  j["starved_s"] = opt(st.starved_s);
  j["blocked_s"] = opt(st.blocked_s);
  j["flops"] = opt(st.flops);
  j["fifo_in_max"] = opt(st.fifo_in_max);
  j["utilization"] = st.busy_s && t->modeled_s > 0 ? json(*st.busy_s / t->modeled_s) : json(nullptr);
  return j;
}

double per_s(double count, double seconds) { return seconds > 0 ? count / seconds : 0.0; }

// The timed back ends' throughput keys (sim/README.md).
void add_timing(json& r, const RunStats& s, const Params& params) {
  const PipelineTiming& t = *s.timing;
  r["modeled_time_s"] = t.modeled_s;
  r["modeled_mpixels_per_s"] = per_s(double(s.pixels_generated), t.modeled_s) / 1e6;
  r["target_met"] = r["modeled_mpixels_per_s"].get<double>() >= params.target_mpixels_per_s;
  r["back_end_mpixels_per_s"] = per_s(double(s.pixels_generated), t.modeled_s - t.dda_starved_s) / 1e6;
  r["bottleneck"] = t.bottleneck;
  r["cache"] = json{{"accesses", t.cache_accesses},
                    {"page_misses", t.page_misses},
                    {"nac", t.page_misses ? double(t.cache_accesses) / double(t.page_misses) : 0.0}};
  r["time_split"] = json{{"dda_busy_s", t.dda_busy_s},
                         {"dda_fifo_full_s", t.dda_fifo_full_s},
                         {"dda_starved_s", t.dda_starved_s},
                         {"had_page_wait_s", t.had_page_wait_s},
                         {"frame_clear_swap_s", t.frame_clear_swap_s}};
  if (s.preparer) {
    r["preparer_triangles_per_s"] = per_s(double(t.preparer_triangles), t.modeled_s);
    r["preparer_capacity_triangles_per_s"] = t.preparer_capacity_triangles_per_s;
    r["target_preparer_triangles_per_s"] = params.target_preparer_triangles_per_s;
  }
}

}  // namespace

json make_report(const ReportContext& ctx, const RunStats& s, const Params& params) {
  json r;
  r["backend"] = ctx.backend;
  r["input"] = ctx.input;
  r["level"] = ctx.level;
  r["frames"] = s.frames;
  r["triangles_in"] = s.triangles_in;
  r["triangles_drawn"] = s.triangles_drawn;
  r["pixels_generated"] = s.pixels_generated;
  r["pixels_written"] = s.had.written;
  r["pixels_blended"] = s.had.blended;
  r["pixels_z_rejected"] = s.had.z_rejected;
  r["pixels_dropped"] = s.had.dropped;
  r["clock_ns"] = params.dda_clock_ns;
  r["target_mpixels_per_s"] = params.target_mpixels_per_s;
  if (s.dda) {
    r["dda_cycles"] = s.dda->cycles;
    r["dda_efficiency"] = s.dda->cycles ? double(s.dda->emitted) / double(s.dda->cycles) : 0.0;
    // Time the DDA alone would need at its clock (no memory side, no front end).
    const double dda_s = double(s.dda->cycles) * params.dda_clock_ns * 1e-9;
    r["dda_bound_time_s"] = dda_s;
    r["dda_bound_mpixels_per_s"] = dda_s > 0 ? double(s.dda->emitted) / dda_s / 1e6 : 0.0;
    json states;
    for (int i = 0; i < static_cast<int>(DdaState::kCount); ++i) states[kDdaStateNames[i]] = s.dda->per_state[i];
    r["dda_states"] = states;
  } else {
    r["dda_cycles"] = nullptr;
    r["dda_efficiency"] = nullptr;
  }
  r["modeled_time_s"] = nullptr;
  r["modeled_mpixels_per_s"] = nullptr;
  r["bottleneck"] = nullptr;
  r["cache"] = json{{"accesses", nullptr}, {"page_misses", nullptr}, {"nac", nullptr}};
  if (s.timing) add_timing(r, s, params);
  json stages = json::object();
  json order = json::array();
  for (const StageStats& st : s.stages) {
    stages[st.name] = stage_json(st, s.timing);
    order.push_back(st.name);
  }
  r["stage_order"] = order;
  r["stages"] = stages;
  if (s.preparer) {
    r["preparer"] = json{{"prepared", s.preparer->prepared},
                         {"degenerate", s.preparer->degenerate},
                         {"off_window", s.preparer->off_window},
                         {"no_lattice_row", s.preparer->no_lattice_row},
                         {"clamped_values", s.preparer->clamped_values}};
  }
  if (s.frontend) {
    const FrontendCounts& f = *s.frontend;
    r["frontend"] = json{{"polygons", f.polygons},
                         {"culled", f.culled},
                         {"clipped", f.clipped},
                         {"clipped_away", f.clipped_away},
                         {"degenerate_polygons", f.degenerate_polygons},
                         {"non_planar", f.non_planar},
                         {"concave", f.concave},
                         {"ear_clipped", f.ear_clipped},
                         {"triangulation_fallbacks", f.triangulation_fallbacks},
                         {"triangles_made", f.triangles_made},
                         {"made_edges", f.made_edges},
                         {"degenerate_triangles", f.degenerate_triangles},
                         {"discarded_off_window", f.discarded_off_window},
                         {"triangles_out", f.triangles_out},
                         {"depth_sort_comparisons", f.depth_sort_comparisons},
                         {"full_sorts", f.full_sorts}};
  } else {
    r["frontend"] = nullptr;  // the input entered below the front end (a triangle or dda trace)
  }
  r["wall_s"] = s.wall_s;
  r["image_sha256"] = ctx.image_sha256;
  r["not_modeled"] = ctx.not_modeled;
  r["warnings"] = ctx.warnings;
  r["config"] = params.source;
  r["rtl_build"] = ctx.rtl_build.empty() ? nlohmann::json() : nlohmann::json(ctx.rtl_build);
  return r;
}

namespace {

std::string num(const json& v, int precision = 4) {
  if (v.is_null()) return "not modeled";
  if (!v.is_number_float()) return v.dump();
  std::ostringstream f;
  f.precision(precision);
  f << v.get<double>();
  return f.str();
}

std::string throughput_markdown(const json& r) {
  std::ostringstream o;
  const double rate = r.at("modeled_mpixels_per_s"), target = r.at("target_mpixels_per_s");
  const double t = r.at("modeled_time_s");
  o << "\n## Throughput\n\n";
  o << (r.at("target_met").get<bool>() ? "PASS" : "FAIL") << ": modeled " << num(rate) << " Mpixel/s against the "
    << num(target) << " Mpixel/s target (" << num(r.at("back_end_mpixels_per_s")) << " Mpixel/s with the DDA fed; "
    << "bottleneck: " << r.at("bottleneck").get<std::string>() << ")\n\n";
  o << "| where the time went | s | share of " << num(t) << " s |\n|---|---|---|\n";
  for (auto it = r.at("time_split").begin(); it != r.at("time_split").end(); ++it)
    o << "| " << it.key() << " | " << num(*it) << " | " << num(it->get<double>() / t * 100, 3) << " % |\n";
  if (r.contains("preparer_triangles_per_s"))
    o << "\nPreparer: delivered " << num(r.at("preparer_triangles_per_s")) << " triangles/s (can do "
      << num(r.at("preparer_capacity_triangles_per_s")) << "; the thesis asks for "
      << num(r.at("target_preparer_triangles_per_s")) << ")\n";
  return o.str();
}

std::string stages_markdown(const json& stages, const json& order) {
  std::ostringstream o;
  o << "| stage | items | busy_s | stall_s | starved_s | blocked_s | utilization | FIFO max in |\n"
    << "|---|---|---|---|---|---|---|---|\n";
  auto cell = [](const json& st, const char* k) { return st.contains(k) ? num(st.at(k)) : std::string("not modeled"); };
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
  auto val = [&](const char* key) -> std::string {
    const json& v = r.at(key);
    if (v.is_null()) return "not modeled";
    if (v.is_number_float()) {
      std::ostringstream f;
      f.precision(4);
      f << v.get<double>();
      return f.str();
    }
    return v.is_string() ? v.get<std::string>() : v.dump();
  };
  o << "# GIRTD render report\n\n";
  o << "| key | value |\n|---|---|\n";
  for (const char* k : {"backend", "input", "level", "frames", "triangles_in", "triangles_drawn",
                        "pixels_generated", "pixels_written", "pixels_blended", "pixels_z_rejected",
                        "pixels_dropped", "dda_cycles", "dda_efficiency", "clock_ns", "modeled_time_s",
                        "modeled_mpixels_per_s", "target_mpixels_per_s", "bottleneck", "wall_s", "image_sha256"})
    o << "| `" << k << "` | " << val(k) << " |\n";
  if (r.contains("dda_bound_mpixels_per_s"))
    o << "| `dda_bound_mpixels_per_s` | " << val("dda_bound_mpixels_per_s") << " |\n";
  const uint64_t gen = r.at("pixels_generated");
  const uint64_t sum = r.at("pixels_written").get<uint64_t>() + r.at("pixels_blended").get<uint64_t>() +
                       r.at("pixels_z_rejected").get<uint64_t>() + r.at("pixels_dropped").get<uint64_t>();
  o << "\nPixel accounting: generated " << gen << " = written + blended + z_rejected + dropped = " << sum
    << (gen == sum ? " (holds)" : " (BROKEN)") << "\n";
  if (r.contains("time_split")) o << throughput_markdown(r);
  if (r.contains("frontend") && r.at("frontend").is_object()) {
    o << "\nFront end (counts over all frames):\n\n| count | value |\n|---|---|\n";
    for (auto it = r.at("frontend").begin(); it != r.at("frontend").end(); ++it)
      o << "| `" << it.key() << "` | " << it->dump() << " |\n";
  }
  o << "\nStages:\n\n" << stages_markdown(r.at("stages"), r.at("stage_order"));
  o << "\nWarnings: " << (r.at("warnings").empty() ? "none" : "") << "\n";
  for (const auto& w : r.at("warnings")) o << "\n- " << w.get<std::string>() << "\n";
  o << "\nNot modeled by this back end: " << (r.at("not_modeled").empty() ? "nothing" : "");
  for (const auto& k : r.at("not_modeled")) o << "`" << k.get<std::string>() << "` ";
  o << "\n";
  return o.str();
}

}  // namespace girtd
