// hw/vram alone against its timing model (sim/vram/vram_port_ticks: busy,
// done, the quiet ticks of the tick warp) and a pixel array (the data): page
// reads and writes as the HAD asks for them (only while the port is free,
// never on a clear's tick), frame clears, buffer swaps and warped ticks,
// (from two clears a run starts with: the RTL's power-up contents are
// anything) under three timings: the thesis' (220 ns cycles, no stolen cycles), a
// fast one with a cycle stolen every 40 ticks, and one whose steals come due
// faster than they are served (the owed count saturates). Every tick: busy,
// done, front and the quiet ticks against the model; every fetch's data
// against the array, which applies a write ending on the tick a fetch is
// taken first, as the RTL does.
#include <iterator>
#include <vector>

#include "Vvram.h"
#include "config/params.hpp"
#include "unit_bench.hpp"
#include "vram/vram_word.hpp"
#include "vram_model.hpp"

namespace {

using girtd::Params;
using unit_bench::get_bits;
using unit_bench::Mismatches;
using unit_bench::Random;
using unit_bench::set_bits;
using unit_bench::VramModel;

struct Counts {
  uint64_t reads = 0, writes = 0, clears = 0, warped = 0;
};

// One timing on a fresh instance (its registers and memory start anything).
Counts run(Vvram& top, const Params& p, uint64_t ticks, Random& r, Mismatches& m) {
  VramModel model(p, 0);
  const girtd::RtlLayout& l = model.layout();
  const int pixels = model.pixels(), cw = l.vram.cell_bits;
  const uint32_t pages = 1u << l.page.number_bits;
  Counts c;
  // A few pages written and read often, so that fetches find what was written.
  std::vector<uint32_t> hot;
  for (int i = 0; i < 8; ++i) hot.push_back(uint32_t(r.below(pages)));
  // About six clears a run, however long a clear takes; the run starts by
  // clearing both buffers (what the RTL holds at power-up is anything).
  const double clear_chance = 6.0 / double(ticks);
  int setup = 0;  // 0: clear, 1: wait, swap, 2: clear, 3: wait, 4: random

  top.clk_i = 0;
  top.rst_ni = 0;
  top.req_i = top.we_i = top.clear_i = top.swap_i = 0;
  top.ticks_i = 1;
  top.cycle_ticks_i = uint32_t(p.ticks(p.vram_cycle_ns));
  top.clear_ticks_i = uint32_t(girtd::frame_clear_ticks(p));
  top.steal_period_ticks_i = uint32_t(p.ticks(p.vram_steal_every_ns));
  top.eval();
  top.clk_i = 1;
  top.eval();
  top.rst_ni = 1;
  for (uint64_t t = 0; t < ticks; ++t) {
    top.clk_i = 0;
    top.req_i = top.we_i = top.clear_i = top.swap_i = 0;
    top.ticks_i = 1;
    top.eval();
    const girtd::VramPortTicks& port = model.port();
    m.check(bool(top.busy_o) == port.busy(), t, "busy " + std::to_string(top.busy_o));
    m.check(bool(top.done_o) == port.done(), t, "done " + std::to_string(top.done_o));
    m.check(bool(top.front_o) == model.front(), t, "front");
    if (model.fetch_done())
      for (int i = 0; i < pixels; ++i)
        m.check(get_bits(&top.rdata_o[0], i * cw, cw) == model.fetched()[size_t(i)], t,
                "fetched cell " + std::to_string(i));
    // hw/vram promises quiet ticks while busy and while nothing is due: the
    // port model's counting ticks.
    const bool promises = port.quiet() || port.port_busy() || port.finishing();
    const uint64_t quiet = promises ? port.counting_ticks(1000) : 0;
    // Otherwise (a steal due or a clear waiting on a free port) it decides now: none.
    m.check(std::min<uint64_t>(top.quiet_o, 1000) == quiet, t,
            "quiet " + std::to_string(top.quiet_o) + ", model " + std::to_string(quiet));
    // The HAD's side: a request only while the port is free; a clear now
    // and then, never with a request; a swap now and then.
    const bool idle = !port.busy() && !port.finishing();
    bool clear = false, swap = false;
    if (setup == 0 || setup == 2)
      clear = true, ++setup;
    else if ((setup == 1 || setup == 3) && idle)
      swap = setup == 1, ++setup;
    else if (setup == 4)
      clear = r.chance(clear_chance), swap = r.chance(2e-4);
    const bool req = setup == 4 && !port.busy() && !clear && r.chance(0.3);
    const bool we = r.chance(0.5);
    const uint32_t page = r.chance(0.8) ? hot[r.below(hot.size())] : uint32_t(r.below(pages));
    std::vector<uint64_t> cells(static_cast<size_t>(pixels));
    for (auto& cell : cells) cell = r.bits(cw);
    const uint32_t bg = uint32_t(r.bits(3 * p.ep_color.out_bits));
    // The tick warp, when nothing is asked for: skip ticks the RTL promises quiet.
    const uint64_t warp = !req && !clear && !swap && quiet >= 1 && r.chance(0.2) ? 1 + r.below(quiet) : 0;
    if (warp) {
      top.ticks_i = uint32_t(warp);
      top.eval();
      top.clk_i = 1;
      top.eval();
      model.count(warp);
      ++c.warped;
      continue;
    }
    top.req_i = req;
    top.we_i = we;
    top.clear_i = clear;
    top.swap_i = swap;
    top.page_i = page;
    top.background_i = bg;
    for (int i = 0; i < pixels; ++i) set_bits(&top.wdata_i[0], i * cw, cw, cells[size_t(i)]);
    top.eval();
    top.clk_i = 1;
    top.eval();
    c.reads += req && !we;
    c.writes += req && we;
    c.clears += clear;
    model.edge(req, we, page, cells, clear, bg, swap);
  }
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  const unit_bench::Args a = unit_bench::parse_args(argc, argv);
  VerilatedContext ctx;
  unit_bench::seed(ctx, a);
  unit_bench::Instances instances;
  Random r(a.seed);
  Mismatches m("vram");
  // Cycles of 15 ns (3 base ticks): a clear of 4 transfers and a cycle stolen
  // every 40 ticks; a clear of 500 transfers (2,000 ticks) and a cycle
  // stolen every 6, so that the steals owed during a clear saturate.
  const struct {
    const char* name;
    Params params;
  } timings[] = {
      {"thesis", Params::defaults()},
      {"steals",
       Params::with_overrides(
           {{"vram", {{"cycle_ns", 15.0}, {"serial_ns", 5.0}, {"serial_transfers", 4}, {"steal_every_ns", 200.0}}}},
           "vram bench")},
      {"saturating",
       Params::with_overrides(
           {{"vram", {{"cycle_ns", 15.0}, {"serial_ns", 5.0}, {"serial_transfers", 500}, {"steal_every_ns", 30.0}}}},
           "vram bench")},
  };
  const uint64_t per_timing = a.ticks / std::size(timings);
  std::string summary = std::to_string(per_timing) + " ticks a timing";
  for (const auto& timing : timings) {
    const Counts c = run(instances.fresh<Vvram>(ctx, timing.name), timing.params, per_timing, r, m);
    summary += "; " + std::to_string(c.reads) + " fetches, " + std::to_string(c.writes) + " writes, " +
               std::to_string(c.clears) + " clears, " + std::to_string(c.warped) + " warps";
  }
  return unit_bench::finish(ctx, a, m, "vram", summary);
}
