#include "config/params.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/input_error.hpp"
#include "common/json_text.hpp"
#include "girtd/default_config.hpp"

namespace girtd {
namespace {

using nlohmann::json;

// Merges `patch` into `base`, refusing keys `base` does not have and values of
// another JSON type: a typo in a config must not be silently ignored.
void merge_strict(json& base, const json& patch, const std::string& path, const std::string& origin) {
  for (auto it = patch.begin(); it != patch.end(); ++it) {
    const std::string key_path = path.empty() ? it.key() : path + "." + it.key();
    if (!base.contains(it.key())) throw InputError(origin, 0, "unknown configuration key '" + key_path + "'");
    json& target = base[it.key()];
    if (target.is_object()) {
      if (!it->is_object()) throw InputError(origin, 0, "'" + key_path + "' must be an object");
      merge_strict(target, *it, key_path, origin);
      continue;
    }
    // A real may replace a real; an integer field takes integers only.
    const bool both_numbers =
        target.is_number() && it->is_number() && (!target.is_number_integer() || it->is_number_integer());
    if (!both_numbers && target.type() != it->type())
      throw InputError(origin, 0, "'" + key_path + "' has the wrong type (expected " +
                                      std::string(target.type_name()) + ")");
    target = *it;
  }
}

int color_out_bits(const json& j) { return j.at("ep").at("color").at("out_bits").get<int>(); }

FixFormat format_of(const json& j, bool has_output) {
  FixFormat f;
  f.int_bits = j.at("int_bits").get<int>();
  f.frac_bits = j.at("frac_bits").get<int>();
  f.out_bits = has_output ? j.at("out_bits").get<int>() : 0;
  return f;
}

void check_format(const FixFormat& f, const char* name, const std::string& origin) {
  if (f.int_bits < 1 || f.frac_bits < 0 || f.total_bits() > 62)
    throw InputError(origin, 0, std::string("ep.") + name + ": int_bits + frac_bits must be 1..62");
  if (f.out_bits > f.int_bits)
    throw InputError(origin, 0, std::string("ep.") + name + ": out_bits exceeds int_bits");
}

Params build(const json& j, const std::string& origin) {
  Params p;
  try {
    p.screen_width = j.at("screen").at("width").get<int>();
    p.screen_height = j.at("screen").at("height").get<int>();
    const json& ep = j.at("ep");
    p.ep_color = format_of(ep.at("color"), true);
    p.ep_t = format_of(ep.at("t"), true);
    p.ep_z = format_of(ep.at("z"), true);
    p.ep_d = format_of(ep.at("d"), false);
    p.xy_bits = ep.at("xy_bits").get<int>();
    p.norm_frac_bits = j.at("nf").at("norm_frac_bits").get<int>();
    p.prom_frac_bits = j.at("nf").at("prom_frac_bits").get<int>();
    const json& dda = j.at("dda");
    p.dda_clock_ns = dda.at("clock_ns").get<double>();
    p.xy_compare_pipelined = dda.at("xy_compare_pipelined").get<bool>();
    p.walk_fix = dda.at("walk_fix").get<bool>();
    p.output_latency_clocks = dda.at("output_latency_clocks").get<int>();
    const std::string omn = j.at("had").at("one_minus_nf").get<std::string>();
    if (omn == "exact") p.one_minus_nf = OneMinusNf::kExact;
    else if (omn == "invert_bits") p.one_minus_nf = OneMinusNf::kInvertBits;
    else throw InputError(origin, 0, "had.one_minus_nf must be \"exact\" or \"invert_bits\"");
    p.had_access_ns = j.at("had").at("access_ns").get<double>();
    p.had_blend_extra_ns = j.at("had").at("blend_extra_ns").get<double>();
    p.had_write_behind = j.at("had").at("write_behind").get<bool>();
    p.had_prefetch = j.at("had").at("prefetch").get<bool>();
    p.had_dirty_bits = j.at("had").at("dirty_bits").get<bool>();
    p.vram_cycle_ns = j.at("vram").at("cycle_ns").get<double>();
    p.vram_serial_ns = j.at("vram").at("serial_ns").get<double>();
    p.vram_serial_transfers = j.at("vram").at("serial_transfers").get<int>();
    p.vram_steal_every_ns = j.at("vram").at("steal_every_ns").get<double>();
    p.base_tick_ns = j.at("timing").at("base_tick_ns").get<double>();
    p.fifo_dda_had_depth = j.at("fifo").at("dda_had_depth").get<int>();
    p.fifo_max_depth = j.at("fifo").at("max_depth").get<int>();
    // The FIFO word is what the DDA's outputs and the HAD's inputs are: a
    // cross-check, so the description cannot claim a layout the design lacks.
    const json& fb = j.at("fifo").at("field_bits");
    const int want[7] = {color_out_bits(j), color_out_bits(j), color_out_bits(j), j.at("nf").at("norm_frac_bits").get<int>() + 1,
                         10, 10, j.at("ep").at("z").at("out_bits").get<int>()};
    const char* names[7] = {"r", "g", "b", "nf", "x", "y", "z"};
    for (int i = 0; i < 7; ++i)
      if (fb.at(names[i]).get<int>() != want[i])
        throw InputError(origin, 0, std::string("fifo.field_bits.") + names[i] + " must be " + std::to_string(want[i]) +
                                        " (the DDA's output and the HAD's input)");
    p.depth_clear = j.at("depth").at("clear").get<int>();
    p.depth_max_mapped = j.at("depth").at("max_mapped").get<int>();
    const json& th = j.at("thesis");
    p.thesis.kc = th.at("kc").get<double>();
    p.thesis.width = th.at("width").get<int>();
    p.thesis.height = th.at("height").get<int>();
    p.thesis.ep_color = format_of(th.at("ep").at("color"), true);
    p.thesis.ep_t = format_of(th.at("ep").at("t"), true);
    p.thesis.ep_z = format_of(th.at("ep").at("z"), true);
    p.thesis.ep_d = format_of(th.at("ep").at("d"), false);
    p.target_mpixels_per_s = j.at("targets").at("mpixels_per_s").get<double>();
    p.stage_flops_per_s = j.at("targets").at("stage_flops_per_s").get<double>();
    p.target_preparer_triangles_per_s = j.at("targets").at("preparer_triangles_per_s").get<double>();
    p.pipeline_fifo_depth = j.at("pipeline").at("fifo_depth").get<int>();
    const std::string sync = j.at("pipeline").at("rtl_sync").get<std::string>();
    if (sync != "token" && sync != "tick") throw InputError(origin, 0, "pipeline.rtl_sync must be \"token\" or \"tick\"");
    p.pipeline_rtl_sync_every_tick = sync == "tick";
    for (const auto& [stage, rate] : j.at("pipeline").at("flops_per_s").items())
      p.stage_rate_flops_per_s[stage] = rate.get<double>();
  } catch (const json::exception& e) {
    throw InputError(origin, 0, std::string("bad configuration: ") + e.what());
  }
  check_format(p.ep_color, "color", origin);
  check_format(p.ep_t, "t", origin);
  check_format(p.ep_z, "z", origin);
  check_format(p.ep_d, "d", origin);
  if (p.ep_color.out_bits != 8 || p.ep_t.out_bits != 8 || p.ep_z.out_bits != 16)
    throw InputError(origin, 0, "the HAD takes 8-bit colour and T and 16-bit Z outputs");
  if (p.norm_frac_bits != 8)
    throw InputError(origin, 0, "nf.norm_frac_bits must be 8: the HAD multiplies 8 x 8 bits");
  if (p.ep_d.frac_bits < p.norm_frac_bits)
    throw InputError(origin, 0, "ep.d.frac_bits must be at least nf.norm_frac_bits");
  if (p.prom_frac_bits < 1 || p.prom_frac_bits * 2 > 16 || p.prom_frac_bits > p.norm_frac_bits)
    throw InputError(origin, 0, "nf.prom_frac_bits must be 1..min(8, norm_frac_bits)");
  if (p.screen_width != 1024 || p.screen_height != 1024)
    throw InputError(origin, 0, "GIRTD's frame is 1024 x 1024 (use a window for smaller pictures)");
  if (p.dda_clock_ns <= 0 || p.had_access_ns <= 0 || p.vram_cycle_ns <= 0 || p.base_tick_ns <= 0 ||
      p.had_blend_extra_ns < 0 || p.vram_serial_ns < 0)
    throw InputError(origin, 0, "clock periods must be positive");
  if (p.vram_steal_every_ns < 0 || p.vram_steal_every_ns / p.base_tick_ns > 16777215 ||
      (p.vram_steal_every_ns > 0 && p.vram_steal_every_ns < 2 * p.vram_cycle_ns))
    throw InputError(origin, 0,
                     "vram.steal_every_ns must be 0 (off) or at least two VRAM cycles and below 2^24 ticks");
  for (double ns : {p.dda_clock_ns, p.had_access_ns, p.had_blend_extra_ns, p.vram_cycle_ns, p.vram_serial_ns}) {
    const double t = ns / p.base_tick_ns;
    if (std::fabs(t - std::round(t)) > 1e-9 || t > 65535)
      throw InputError(origin, 0, "every period must be a multiple of timing.base_tick_ns (at most 65535 ticks)");
  }
  if (p.fifo_dda_had_depth < 1 || p.fifo_dda_had_depth > p.fifo_max_depth)
    throw InputError(origin, 0, "fifo.dda_had_depth must be 1..fifo.max_depth");
  // Run-time knobs must fit the RTL's ports (hw/backend): 8-bit DDA period,
  // 16-bit HAD and VRAM times, 24-bit clear and steal periods.
  if (p.ticks(p.dda_clock_ns) > 255) throw InputError(origin, 0, "dda.clock_ns must be at most 255 base ticks");
  if (uint64_t(p.vram_serial_transfers) * uint64_t(p.ticks(p.vram_serial_ns) + p.ticks(p.vram_cycle_ns)) > 16777215 ||
      p.vram_serial_transfers < 0)
    throw InputError(origin, 0, "the frame clear (vram.serial_transfers x (serial_ns + cycle_ns)) must be below 2^24 ticks");
  if (p.pipeline_fifo_depth < 1 || p.pipeline_fifo_depth > 1000000)
    throw InputError(origin, 0, "pipeline.fifo_depth must be 1..1000000 items");
  for (const auto& [stage, rate] : p.stage_rate_flops_per_s)
    if (!(rate > 0) || !std::isfinite(rate))
      throw InputError(origin, 0, "pipeline.flops_per_s." + stage + " must be a positive rate");
  p.source = j;
  return p;
}

json builtin_json() { return json::parse(kDefaultConfigJson); }

}  // namespace

Params Params::defaults() { return build(builtin_json(), kDefaultConfigPath); }

Params Params::with_overrides(const json& override_json, const std::string& origin) {
  json merged = builtin_json();
  if (!override_json.is_object()) throw InputError(origin, 0, "a configuration must be a JSON object");
  merge_strict(merged, override_json, "", origin);
  return build(merged, origin);
}

Params Params::with_thesis_formats() const {
  Params t = *this;
  t.ep_color = thesis.ep_color;
  t.ep_t = thesis.ep_t;
  t.ep_z = thesis.ep_z;
  t.ep_d = thesis.ep_d;
  return t;
}

Params Params::from_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open configuration file");
  std::ostringstream text;
  text << in.rdbuf();
  return with_overrides(parse_json_text(text.str(), path), path);
}

}  // namespace girtd
