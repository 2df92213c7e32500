#include "config/params.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "config/config_layers.hpp"
#include "config/rtl_widths.hpp"
#include "girtd/design_constants.hpp"

namespace girtd {
namespace {

using nlohmann::json;

// Reads the merged configuration by dotted key and refuses a value at the
// line that set it.
class Reader {
 public:
  explicit Reader(const ConfigLayers& c) : c_(c) {}

  const json& at(const std::string& key) const {
    std::string pointer = "/" + key;
    for (char& ch : pointer)
      if (ch == '.') ch = '/';
    return c_.merged().at(json::json_pointer(pointer));
  }
  int integer(const std::string& key, int lo, int hi) const {
    const json& v = at(key);
    const int64_t x = v.get<int64_t>();
    if (x < lo || x > hi) fail(key, "must be " + std::to_string(lo) + ".." + std::to_string(hi));
    return static_cast<int>(x);
  }
  double real(const std::string& key) const {
    const double x = at(key).get<double>();
    if (!std::isfinite(x)) fail(key, "must be a finite number");
    return x;
  }
  // An integer that is a field width in bits of some address: a power of two.
  int power_of_two(const std::string& key, int lo, int hi, const std::string& why) const {
    const int v = integer(key, lo, hi);
    if ((v & (v - 1)) != 0) fail(key, "must be a power of two (" + why + ")");
    return v;
  }
  bool flag(const std::string& key) const { return at(key).get<bool>(); }
  std::string text(const std::string& key) const { return at(key).get<std::string>(); }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const { throw c_.error(key, what); }
  // A relation between keys fails at the one the user set last.
  [[noreturn]] void fail_relation(const std::vector<std::string>& keys, const std::string& what) const {
    const std::string key = c_.last_set(keys);
    throw c_.error(key, what);
  }

 private:
  const ConfigLayers& c_;
};

FixFormat format_of(const Reader& r, const std::string& key, bool has_output) {
  FixFormat f;
  f.int_bits = r.integer(key + ".int_bits", 1, 61);
  f.frac_bits = r.integer(key + ".frac_bits", 0, 61);
  f.out_bits = has_output ? r.integer(key + ".out_bits", 1, 32) : 0;
  if (f.total_bits() > 62) r.fail(key + ".frac_bits", "int_bits + frac_bits must be at most 62");
  if (f.out_bits > f.int_bits) r.fail(key + ".out_bits", "exceeds int_bits");
  return f;
}

// A period: positive (or >= 0), a whole number of base ticks, at most `max_ticks`.
double period(const Reader& r, const std::string& key, double base_tick_ns, bool may_be_zero, int64_t max_ticks) {
  const double ns = r.real(key);
  if (ns < 0 || (!may_be_zero && ns == 0)) r.fail(key, may_be_zero ? "must not be negative" : "must be positive");
  const double t = ns / base_tick_ns;
  if (std::fabs(t - std::round(t)) > 1e-9) r.fail(key, "must be a multiple of timing.base_tick_ns");
  if (t > double(max_ticks)) r.fail(key, "must be at most " + std::to_string(max_ticks) + " base ticks (the RTL's port)");
  return ns;
}

Params build(const ConfigLayers& layers) {
  const Reader r(layers);
  Params p;
  try {
    // The screen, the output widths and nf's fraction are the design's
    // constants (config/constants.json: a configuration cannot change them).
    p.screen_width = r.integer("screen.width", kScreenWidth, kScreenWidth);
    p.screen_height = r.integer("screen.height", kScreenHeight, kScreenHeight);
    p.ep_color = format_of(r, "ep.color", true);
    p.ep_t = format_of(r, "ep.t", true);
    p.ep_z = format_of(r, "ep.z", true);
    p.ep_d = format_of(r, "ep.d", false);
    p.xy_bits = r.integer("ep.xy_bits", 11, 32);  // X, Y up to 1023 and a sign
    p.wrap_guard_bits = r.integer("ep.wrap_guard_bits", 1, 32);
    p.norm_frac_bits = r.integer("nf.norm_frac_bits", kNormFracBits, kNormFracBits);
    p.prom_frac_bits = r.integer("nf.prom_frac_bits", 1, 8);
    if (p.ep_d.frac_bits < p.norm_frac_bits)
      r.fail_relation({"ep.d.frac_bits", "nf.norm_frac_bits"}, "ep.d.frac_bits must be at least nf.norm_frac_bits");

    p.base_tick_ns = r.real("timing.base_tick_ns");
    if (!(p.base_tick_ns > 0) || p.base_tick_ns > 1e6) r.fail("timing.base_tick_ns", "must be above 0 and at most 1e6 ns");
    p.dda_clock_ns = period(r, "dda.clock_ns", p.base_tick_ns, false, max_of_bits(kRtlDdaPeriodBits));
    p.xy_compare_pipelined = r.flag("dda.xy_compare_pipelined");
    p.walk_fix = r.flag("dda.walk_fix");
    p.output_latency_clocks = r.integer("dda.output_latency_clocks", 1, 8);
    if (!r.at("dda.q_override").is_null()) {
      p.q_override = r.real("dda.q_override");
      if (!(*p.q_override >= 0 && *p.q_override <= 64)) r.fail("dda.q_override", "must be null or 0..64");
    }

    const std::string far = r.text("preparer.far_edges");
    if (far != "as_computed" && far != "constant") r.fail("preparer.far_edges", "must be \"as_computed\" or \"constant\"");
    p.far_edges_constant = far == "constant";
    const std::string fill = r.text("preparer.fill_rule");
    if (fill != "inclusive" && fill != "top_left") r.fail("preparer.fill_rule", "must be \"inclusive\" or \"top_left\"");
    p.fill_top_left = fill == "top_left";
    p.edge_flags = r.flag("preparer.edge_flags");
    const std::string steep = r.text("preparer.steep_attributes");
    if (steep != "as_computed" && steep != "limited")
      r.fail("preparer.steep_attributes", "must be \"as_computed\" or \"limited\"");
    p.steep_limited = steep == "limited";

    p.cull_objects = r.flag("culling.objects");
    const std::string back = r.text("culling.back_faces");
    if (back != "scene" && back != "always") r.fail("culling.back_faces", "must be \"scene\" or \"always\"");
    p.cull_back_faces_always = back == "always";

    const std::string omn = r.text("had.one_minus_nf");
    if (omn == "exact") p.one_minus_nf = OneMinusNf::kExact;
    else if (omn == "invert_bits") p.one_minus_nf = OneMinusNf::kInvertBits;
    else r.fail("had.one_minus_nf", "must be \"exact\" or \"invert_bits\"");
    p.had_access_ns = period(r, "had.access_ns", p.base_tick_ns, false, max_of_bits(kRtlTimeBits));
    p.had_blend_extra_ns = period(r, "had.blend_extra_ns", p.base_tick_ns, true, max_of_bits(kRtlTimeBits));
    p.had_write_behind = r.flag("had.write_behind");
    p.had_prefetch = r.flag("had.prefetch");
    p.had_dirty_bits = r.flag("had.dirty_bits");
    p.cache_pages = r.power_of_two("cache.pages", 1, 64, "a page's slot is bits of its number");
    p.cache_page_width = r.power_of_two("cache.page_width", 1, 1024, "the page is a field of the pixel address");
    p.cache_page_height = r.power_of_two("cache.page_height", 1, 1024, "the page is a field of the pixel address");
    if (p.cache_page_width * p.cache_page_height > 64 || p.cache_page_width * p.cache_page_height < 2)
      r.fail_relation({"cache.page_width", "cache.page_height"}, "a page holds 2 to 64 pixels (page_width x page_height)");

    p.vram_cycle_ns = period(r, "vram.cycle_ns", p.base_tick_ns, false, max_of_bits(kRtlTimeBits));
    p.vram_serial_ns = period(r, "vram.serial_ns", p.base_tick_ns, true, max_of_bits(kRtlTimeBits));
    const int64_t long_max = max_of_bits(kRtlLongTimeBits);
    p.vram_serial_transfers = r.integer("vram.serial_transfers", 0, static_cast<int>(long_max));
    if (int64_t(p.vram_serial_transfers) * (p.ticks(p.vram_serial_ns) + p.ticks(p.vram_cycle_ns)) > long_max)
      r.fail_relation({"vram.serial_transfers", "vram.serial_ns", "vram.cycle_ns"}, "the frame clear (serial_transfers x (serial_ns + cycle_ns)) must be at most " +
                                          std::to_string(long_max) + " base ticks (the RTL's port)");
    p.vram_steal_every_ns = period(r, "vram.steal_every_ns", p.base_tick_ns, true, long_max);
    if (p.vram_steal_every_ns > 0 && p.vram_steal_every_ns < 2 * p.vram_cycle_ns)
      r.fail_relation({"vram.steal_every_ns", "vram.cycle_ns"}, "vram.steal_every_ns must be 0 (off) or at least two VRAM cycles");

    // The RTL FIFO is built max_depth deep (2.. so its pointer has a bit;
    // up to 4096, a memory Verilator still builds in a minute).
    p.fifo_max_depth = r.integer("fifo.max_depth", 2, 4096);
    p.fifo_dda_had_depth = r.integer("fifo.dda_had_depth", 1, 4096);
    if (p.fifo_dda_had_depth > p.fifo_max_depth)
      r.fail_relation({"fifo.dda_had_depth", "fifo.max_depth"}, "fifo.dda_had_depth must be at most fifo.max_depth");

    const int z_max = static_cast<int>(max_of_bits(p.ep_z.out_bits));  // the VRAM's Z field
    p.depth_clear = r.integer("depth.clear", 0, z_max);
    p.depth_max_mapped = r.integer("depth.max_mapped", 0, z_max);
    if (p.depth_max_mapped >= p.depth_clear)
      r.fail_relation({"depth.max_mapped", "depth.clear"}, "depth.max_mapped must be below depth.clear (a drawn pixel must pass the cleared Z)");

    p.thesis.kc = r.real("thesis.kc");
    if (!(p.thesis.kc > 0)) r.fail("thesis.kc", "must be positive");
    p.thesis.width = r.integer("thesis.width", 1, 1024);
    p.thesis.height = r.integer("thesis.height", 1, 1024);
    p.thesis.ep_color = format_of(r, "thesis.ep.color", true);
    p.thesis.ep_t = format_of(r, "thesis.ep.t", true);
    p.thesis.ep_z = format_of(r, "thesis.ep.z", true);
    p.thesis.ep_d = format_of(r, "thesis.ep.d", false);

    p.target_mpixels_per_s = r.real("targets.mpixels_per_s");
    p.stage_flops_per_s = r.real("targets.stage_flops_per_s");
    p.target_preparer_triangles_per_s = r.real("targets.preparer_triangles_per_s");
    for (const char* key : {"targets.mpixels_per_s", "targets.stage_flops_per_s", "targets.preparer_triangles_per_s"})
      if (!(r.real(key) > 0)) r.fail(key, "must be positive");

    p.pipeline_fifo_depth = r.integer("pipeline.fifo_depth", 1, 1000000);
    const std::string sync = r.text("pipeline.rtl_sync");
    if (sync != "token" && sync != "tick") r.fail("pipeline.rtl_sync", "must be \"token\" or \"tick\"");
    p.pipeline_rtl_sync_every_tick = sync == "tick";
    for (const auto& [stage, rate] : r.at("pipeline.flops_per_s").items()) {
      const std::string key = "pipeline.flops_per_s." + stage;
      if (!(r.real(key) > 0)) r.fail(key, "must be a positive rate");
      p.stage_rate_flops_per_s[stage] = rate.get<double>();
    }
  } catch (const json::exception& e) {
    throw InputError(layers.files().empty() ? std::string("--config") : layers.files().back(), 0,
                     std::string("bad configuration: ") + e.what());
  }
  p.source = layers.merged();
  return p;
}

}  // namespace

Params Params::defaults() { return build(ConfigLayers::builtin()); }

Params Params::with_overrides(const json& override_json, const std::string& origin) {
  ConfigLayers layers = ConfigLayers::builtin();
  layers.merge_json(override_json, origin);
  return build(layers);
}

Params Params::from_layers(const ConfigLayers& layers) { return build(layers); }

Params Params::from_files(const std::vector<std::string>& paths) {
  ConfigLayers layers = ConfigLayers::builtin();
  for (const std::string& path : paths) layers.merge_file(path);
  return build(layers);
}

Params Params::with_thesis_formats() const {
  Params t = *this;
  t.ep_color = thesis.ep_color;
  t.ep_t = thesis.ep_t;
  t.ep_z = thesis.ep_z;
  t.ep_d = thesis.ep_d;
  return t;
}

}  // namespace girtd
