// Run-time view of config/girtd.json. Every field comes from the JSON (the
// built-in copy, optionally overridden by a user file); nothing here has a
// default of its own, so a width or timing is never written twice.
#pragma once

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/fixed_point.hpp"

namespace girtd {

class ConfigLayers;  // config/config_layers.hpp

enum class OneMinusNf { kExact, kInvertBits };

// The thesis appendix's validation program (docs/design.md §11): its screen and
// its 32-bit register formats, on the same scales as the hardware EPs
// (colour 0..255, T 0..256, Z 0..65535, D in pixels).
struct ThesisParams {
  double kc;       // screen map x = KC (1 + xp), y = KC (0.75 - yp)
  int width, height;
  FixFormat ep_color, ep_t, ep_z, ep_d;
};

struct Params {
  int screen_width;
  int screen_height;

  FixFormat ep_color;  // R, G, B
  FixFormat ep_t;      // transparency T (0..256 scale, 255 at the output = 1.0)
  FixFormat ep_z;
  FixFormat ep_d;      // edge distances D1..D3 (no output saturation)
  int xy_bits;
  // The wrap detector (a simulation aid, golden and RTL alike): each EP's
  // register is carried with this many guard bits above its width (at most
  // 64 bits in all), and a value whose guard bits are not its sign wrapped.
  int wrap_guard_bits;
  int guard_bits(const FixFormat& f) const { return std::min(wrap_guard_bits, 64 - f.total_bits()); }

  int norm_frac_bits;  // n_i and nf fraction bits (1.8)
  int prom_frac_bits;  // operand fraction bits of the U >= 2 product table (1.4)

  double dda_clock_ns;
  bool xy_compare_pipelined;  // TTL option: +1 clock at every run end
  bool walk_fix;              // robust start/walk (docs/design.md §11); false = DDApix as written
  int output_latency_clocks;  // fig. 4.17 output registers
  // Every frame's antialiasing width Q, over the input's own (config
  // dda.q_override; nullopt: the input's). Applied as inputs are read.
  std::optional<double> q_override;

  // The preparer's fixes for the design's limits (config `preparer`; all off
  // in the thesis' design, on in config/presets/robust.json).
  bool far_edges_constant;  // an edge whose line misses the pixel box goes out as a constant: no D wraps
  bool fill_top_left;       // a shared edge is evaluated alike from both sides; its ties go to one side
  bool edge_flags;          // a triangle's interior edges (Triangle::interior_edges) get no AA fringe
  bool steep_limited;       // an attribute steep enough to leave its EP over the walk is cut across: no wraps

  // Culling in front of lighting (config `culling`; off in the thesis'
  // design, on in config/presets/culling.json).
  bool cull_objects;            // whole objects whose bounding sphere misses the view volume
  bool cull_back_faces_always;  // "always": every frame culls back faces (transparent surfaces exempt); "scene": as the input says

  OneMinusNf one_minus_nf;
  double had_access_ns;
  double had_blend_extra_ns;  // multiplier + adder time of a blended pixel (§6)
  bool had_write_behind;      // 5.2.2 improvements, off in the thesis' design
  bool had_prefetch;
  bool had_dirty_bits;        // skip writing back a page no pixel was written to
  int cache_pages;            // pages in the HAD's cache (direct-mapped)
  int cache_page_width;       // a cache page (one VRAM cycle): pixels in X ...
  int cache_page_height;      // ... and in Y (16 x 1 in the thesis)
  double vram_cycle_ns;
  double vram_serial_ns;      // serial-port transfer, used by the frame clear (§7)
  int vram_serial_transfers;
  double vram_steal_every_ns;  // refresh / scan-out takes one VRAM cycle this often (0: never)
  double base_tick_ns;        // the RTL back end's common clock; every period is a multiple

  int fifo_dda_had_depth;
  int fifo_max_depth;         // the RTL FIFO is built this deep; dda_had_depth is a run-time limit

  // A period in base ticks (exact: build() checks the multiples).
  int ticks(double ns) const { return static_cast<int>(ns / base_tick_ns + 0.5); }
  int depth_clear;
  int depth_max_mapped;

  ThesisParams thesis;

  // The timed pipeline (sim/pipeline): a FIFO of this many items between
  // every pair of stages; each front-end stage's arithmetic rate, flop/s.
  int pipeline_fifo_depth;
  // How the Verilated back end keeps step with SystemC time: "token" (only
  // when a token changes hands; it runs ahead in between) or "tick" (every
  // base tick, for measuring what that costs).
  bool pipeline_rtl_sync_every_tick;
  std::map<std::string, double> stage_rate_flops_per_s;

  double target_mpixels_per_s;
  double stage_flops_per_s;           // the thesis' budget per stage (a target, not the model)
  double target_preparer_triangles_per_s;

  nlohmann::json source;  // the merged JSON, echoed into reports

  // The built-in configuration (config/girtd.json at build time).
  static Params defaults();
  // Built-in configuration with `override_json` merged over it. Unknown keys
  // and wrong types raise InputError naming `origin`.
  static Params with_overrides(const nlohmann::json& override_json, const std::string& origin);
  // --config FILE...: each file merged over the built-in one in order, the
  // later winning; a refused value is reported at its key's line.
  static Params from_files(const std::vector<std::string>& paths);
  // Layers already merged (files and JSON patches in the caller's order).
  static Params from_layers(const ConfigLayers& layers);

  // These parameters with the thesis program's formats in place of the
  // hardware EPs' (the DDA datapath then is the program's 32-bit registers).
  Params with_thesis_formats() const;
};

}  // namespace girtd
