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

json stage_json(const StageStats& st) {
  return json{{"items", st.items}, {"busy_s", opt(st.busy_s)}, {"stall_s", opt(st.stall_s)}};
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
  json stages = json::object();
  for (const StageStats& st : s.stages) stages[st.name] = stage_json(st);
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
  r["config"] = params.source;
  return r;
}

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
  if (r.contains("frontend") && r.at("frontend").is_object()) {
    o << "\nFront end (counts over all frames):\n\n| count | value |\n|---|---|\n";
    for (auto it = r.at("frontend").begin(); it != r.at("frontend").end(); ++it)
      o << "| `" << it.key() << "` | " << it->dump() << " |\n";
  }
  o << "\nStages:\n\n| stage | items | busy_s | stall_s |\n|---|---|---|---|\n";
  for (auto it = r.at("stages").begin(); it != r.at("stages").end(); ++it) {
    auto show = [](const json& v) { return v.is_null() ? std::string("not modeled") : v.dump(); };
    o << "| " << it.key() << " | " << it->at("items") << " | " << show(it->at("busy_s")) << " | "
      << show(it->at("stall_s")) << " |\n";
  }
  o << "\nNot modeled by this back end: ";
  for (const auto& k : r.at("not_modeled")) o << "`" << k.get<std::string>() << "` ";
  o << "\n";
  return o.str();
}

}  // namespace girtd
