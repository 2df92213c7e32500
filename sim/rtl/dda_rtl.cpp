#include "rtl/dda_rtl.hpp"

#include <stdexcept>
#include <type_traits>

#include "Vdda.h"
#include "common/triangle_setup.hpp"
#include "verilated.h"
#if VM_COVERAGE
#include "verilated_cov.h"
#endif

namespace girtd {
namespace {

template <typename Port>
void set_port(Port& port, int64_t value, int bits) {
  const uint64_t mask = bits >= 64 ? ~uint64_t{0} : ((uint64_t{1} << bits) - 1);
  port = static_cast<std::remove_reference_t<Port>>(static_cast<uint64_t>(value) & mask);
}

}  // namespace

struct DdaRtl::Impl {
  const Params& params;
  VerilatedContext ctx;
  std::unique_ptr<Vdda> top;

  Impl(const Params& p, uint32_t x_seed) : params(p) {
    if (x_seed != 0) {
      ctx.randReset(2);
      ctx.randSeed(static_cast<int>(x_seed));
    }
    top = std::make_unique<Vdda>(&ctx);
    top->walk_fix_i = p.walk_fix;
    top->pipelined_compare_i = p.xy_compare_pipelined;
    top->in_valid_i = 0;
    top->out_ready_i = 1;
    top->rst_ni = 0;
    for (int i = 0; i < 3; ++i) tick();
    top->rst_ni = 1;
  }

  void tick() {
    top->clk_i = 0;
    top->eval();
    top->clk_i = 1;
    top->eval();
    top->clk_i = 0;
    top->eval();
  }

  void load_ports(const DdaParams& d) {
    const int xy = params.xy_bits;
    set_port(top->x0_i, d.x0, xy);
    set_port(top->y0_i, d.y0, xy);
    set_port(top->xmin_i, d.xmin, xy);
    set_port(top->xmax_i, d.xmax, xy);
    set_port(top->ymax_i, d.ymax, xy);
    top->q_zero_i = d.q == 0;
    set_port(top->q_k_i, d.q == 0 ? 0 : q_log2(d.q), 4);
    const int cw = params.ep_color.total_bits(), tw = params.ep_t.total_bits(), zw = params.ep_z.total_bits(),
              dw = params.ep_d.total_bits();
    auto ep = [&](auto& v, auto& dx, auto& dy, const EpInit& e, int w) {
      set_port(v, e.v, w);
      set_port(dx, e.dx, w);
      set_port(dy, e.dy, w);
    };
    ep(top->r_i, top->r_dx_i, top->r_dy_i, d.ep[kEpR], cw);
    ep(top->g_i, top->g_dx_i, top->g_dy_i, d.ep[kEpG], cw);
    ep(top->b_i, top->b_dx_i, top->b_dy_i, d.ep[kEpB], cw);
    ep(top->t_i, top->t_dx_i, top->t_dy_i, d.ep[kEpT], tw);
    ep(top->z_i, top->z_dx_i, top->z_dy_i, d.ep[kEpZ], zw);
    ep(top->d1_i, top->d1_dx_i, top->d1_dy_i, d.ep[kEpD1], dw);
    ep(top->d2_i, top->d2_dx_i, top->d2_dy_i, d.ep[kEpD2], dw);
    ep(top->d3_i, top->d3_dx_i, top->d3_dy_i, d.ep[kEpD3], dw);
  }
};

DdaRtl::DdaRtl(const Params& p, uint32_t x_seed) : impl_(std::make_unique<Impl>(p, x_seed)) {}
DdaRtl::~DdaRtl() { impl_->top->final(); }

DdaRtlResult DdaRtl::run(const DdaParams& in, const DdaEngine::PixelSink& sink, const DdaRtlOptions& opt) {
  Impl& m = *impl_;
  Vdda& top = *m.top;
  std::mt19937 rng(opt.seed);
  std::bernoulli_distribution refuse(opt.stall_probability);

  // Wait for the DDA to accept, then load.
  m.load_ports(in);
  top.in_valid_i = 1;
  top.out_ready_i = 1;
  top.eval();
  for (int guard = 0; !top.in_ready_o; ++guard) {
    if (guard > 1000) throw std::logic_error("RTL DDA never became ready");
    m.tick();
  }
  m.tick();  // the LOAD clock
  top.in_valid_i = 0;

  DdaRtlResult res;
  uint64_t clocks = 0;  // non-stalled clocks since the first CHECK: the golden model's cycle numbering
  const uint64_t bound = 64 * uint64_t(in.xmax - in.xmin + 3) * uint64_t(in.ymax - in.y0 + 3) + 1000;
  for (;;) {
    top.out_ready_i = opt.stall_probability > 0 ? !refuse(rng) : 1;
    top.eval();
    const bool idle = top.state_o == 8;
    if (idle && !top.out_valid_o) break;
    if (top.out_valid_o && top.out_ready_i && sink) {
      DdaEmit e;
      e.pixel.x = top.out_x_o;
      e.pixel.y = top.out_y_o;
      e.pixel.r = top.out_r_o;
      e.pixel.g = top.out_g_o;
      e.pixel.b = top.out_b_o;
      e.pixel.z = top.out_z_o;
      e.pixel.nf = top.out_nf_o;
      e.cycle = clocks;
      sink(e);
    }
    if (top.out_valid_o && top.out_ready_i) ++res.stats.emitted;
    if (top.active_o) {
      ++res.stats.cycles;
      ++res.stats.per_state[top.state_o];
    }
    if (top.stall_o) ++res.stall_cycles;
    if (!(top.out_valid_o && !top.out_ready_i)) ++clocks;
    m.tick();
    if (clocks + res.stall_cycles > bound) throw std::logic_error("RTL DDA did not finish");
  }
  return res;
}

void DdaRtl::write_coverage(const std::string& path) const {
#if VM_COVERAGE
  impl_->ctx.coveragep()->write(path.c_str());
#else
  (void)path;
#endif
}

}  // namespace girtd
