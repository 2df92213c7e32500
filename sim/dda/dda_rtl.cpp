#include "dda/dda_rtl.hpp"

#include <stdexcept>

#include "Vdda.h"
#include "dda/dda_port_access.hpp"
#include "verilated.h"
#if VM_COVERAGE
#include "verilated_cov.h"
#endif

namespace girtd {

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
    top->en_i = 1;  // one DDA clock per tick: this harness drives the DDA alone
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

  void load_ports(const DdaParams& d) { load_dda_ports(*top, d, params); }
};

DdaRtl::DdaRtl(const Params& p, uint32_t x_seed) : impl_(std::make_unique<Impl>(p, x_seed)) {
  require_rtl_build(p);
}
DdaRtl::~DdaRtl() { impl_->top->final(); }

DdaRtlResult DdaRtl::run(const DdaParams& in, const DdaEngine::PixelSink& sink, const DdaRtlOptions& opt) {
  Impl& m = *impl_;
  Vdda& top = *m.top;
  std::mt19937 rng(opt.seed);
  std::bernoulli_distribution refuse(opt.stall_probability);

  // The numerics counters run on across parameter sets: this run's are the difference.
  const EpNumerics before = read_numerics(top, {});

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
  const EpNumerics after = read_numerics(top, {});
  EpNumerics& n = res.stats.numerics;
  for (int i = 0; i < kEpCount; ++i) {
    n.ep[i].wraps = after.ep[i].wraps - before.ep[i].wraps;
    n.ep[i].saturations = after.ep[i].saturations - before.ep[i].saturations;
  }
  n.triangles_affected = after.triangles_affected - before.triangles_affected;
  if (n.triangles_affected) n.first_affected_line = in.source_line;
  res.stats.triangles = 1;
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
