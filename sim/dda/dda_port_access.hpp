// Loading a DDA parameter set onto the ports of a Verilated top (the dda
// top and the back-end top have the same parameter port).
#pragma once

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"
#include "config/params.hpp"
#include "dda/dda_params.hpp"
#include "dda/ep_numerics.hpp"
#include "layout/rtl_layout.hpp"
#include "layout/rtl_package.hpp"
#include "rtl_build.hpp"

namespace girtd {

// Widths, layouts and depths are elaboration values of the Verilated RTL
// (rtl_build.hpp, models/layout/rtl_package.hpp): a configuration that asks
// for others needs another build (an RTL variant), never a silently wrong run.
inline void require_rtl_build(const Params& p) {
  if (rtl_build_key(p) == kRtlBuildKey) return;
  throw InputError("--config", 0,
                   "this RTL build (" + std::string(kRtlBuildKey) + ") is elaborated for other values: " +
                       rtl_build_differences(nlohmann::json::parse(kRtlBuildValues), rtl_build_values(p)));
}

template <typename Port>
void set_port(Port& port, int64_t value, int bits) {
  const uint64_t mask = bits >= 64 ? ~uint64_t{0} : ((uint64_t{1} << bits) - 1);
  port = static_cast<std::remove_reference_t<Port>>(static_cast<uint64_t>(value) & mask);
}

// The DDA's numerics counters (hw/dda/dda_limits.sv): COUNT_W = 32 bits
// each, one word of Verilator's wide ports apiece. `lines`: the source line
// of each parameter set taken, in order (for the first affected one).
template <typename Top>
EpNumerics read_numerics(const Top& top, const std::vector<int>& lines) {
  static_assert(kRtlCountBits == 32, "one counter per 32-bit word of the wide port");
  EpNumerics n;
  for (int i = 0; i < kEpCount; ++i) n.ep[i].wraps = top.wraps_o[i];
  for (int i = 0; i < 5; ++i) n.ep[i].saturations = top.clips_o[i];
  n.triangles_affected = top.triangles_affected_o;
  n.first_affected = top.first_affected_o;
  if (n.first_affected > 0 && n.first_affected <= lines.size()) n.first_affected_line = lines[n.first_affected - 1];
  return n;
}

template <typename Top>
void load_dda_ports(Top& top, const DdaParams& d, const Params& params) {
  const int xy = params.xy_bits;
  set_port(top.x0_i, d.x0, xy);
  set_port(top.y0_i, d.y0, xy);
  set_port(top.xmin_i, d.xmin, xy);
  set_port(top.xmax_i, d.xmax, xy);
  set_port(top.ymax_i, d.ymax, xy);
  top.q_zero_i = d.q == 0;
  set_port(top.q_k_i, d.q == 0 ? 0 : q_log2(d.q), kRtlQExponentBits);
  set_port(top.hard_edges_i, d.hard_edges, 3);
  top.clamped_i = d.clamped;
  auto ep = [](auto& v, auto& dx, auto& dy, const EpInit& e, int w) {
    set_port(v, e.v, w);
    set_port(dx, e.dx, w);
    set_port(dy, e.dy, w);
  };
  const int cw = params.ep_color.total_bits(), tw = params.ep_t.total_bits(), zw = params.ep_z.total_bits(),
            dw = params.ep_d.total_bits();
  ep(top.r_i, top.r_dx_i, top.r_dy_i, d.ep[kEpR], cw);
  ep(top.g_i, top.g_dx_i, top.g_dy_i, d.ep[kEpG], cw);
  ep(top.b_i, top.b_dx_i, top.b_dy_i, d.ep[kEpB], cw);
  ep(top.t_i, top.t_dx_i, top.t_dy_i, d.ep[kEpT], tw);
  ep(top.z_i, top.z_dx_i, top.z_dy_i, d.ep[kEpZ], zw);
  ep(top.d1_i, top.d1_dx_i, top.d1_dy_i, d.ep[kEpD1], dw);
  ep(top.d2_i, top.d2_dx_i, top.d2_dy_i, d.ep[kEpD2], dw);
  ep(top.d3_i, top.d3_dx_i, top.d3_dy_i, d.ep[kEpD3], dw);
}

}  // namespace girtd
