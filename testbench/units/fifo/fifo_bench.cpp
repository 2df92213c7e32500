// hw/fifo/pixel_fifo alone against a queue: constrained-random pushes and pops
// (never a push into a full FIFO without a pop, never a pop from an empty
// one: the unit's own assertions) in phases that fill it, drain it and hover,
// under run-time limits from 1 to the built depth. Every tick: count, full,
// empty and the head's data against the queue. Two builds: the thesis' (69
// bits, 32 deep) and a small one (8 bits, 5 deep: a depth that is no power
// of two).
#include <array>
#include <deque>

#include "Vpixel_fifo.h"
#include "Vpixel_fifo_small.h"
#include "unit_bench.hpp"

namespace {

using unit_bench::Mismatches;
using unit_bench::Random;
using Word = std::array<uint32_t, 3>;

void put(VlWide<3>& d, const Word& w) {
  for (int i = 0; i < 3; ++i) d[i] = w[size_t(i)];
}
void put(CData& d, const Word& w) { d = CData(w[0]); }
Word get(const VlWide<3>& d) { return {d[0], d[1], d[2]}; }
Word get(CData d) { return {d, 0, 0}; }

Word random_word(Random& r, int width) {
  Word w{};
  for (int i = 0; i < 3; ++i) {
    const int bits = std::min(32, width - 32 * i);
    if (bits > 0) w[size_t(i)] = uint32_t(r.bits(bits));
  }
  return w;
}

struct Counts {
  uint64_t pushes = 0, pops = 0, full_ticks = 0;
};

template <typename Top>
Counts run(Top& top, int depth, int width, uint64_t ticks, Random& r, Mismatches& m) {
  std::deque<Word> model;
  Counts c;
  top.clk_i = 0;
  top.rst_ni = 0;
  top.push_i = top.pop_i = 0;
  top.limit_i = depth;
  top.eval();
  top.clk_i = 1;
  top.eval();
  top.rst_ni = 1;
  double p_push = 0.5, p_pop = 0.5;
  int limit = depth;
  for (uint64_t t = 0; t < ticks; ++t) {
    if (t % 97 == 0) {  // a new phase: fill, drain or hover, under a new limit now and then
      const int phase = int(r.below(3));
      p_push = phase == 0 ? 0.9 : phase == 1 ? 0.1 : 0.5;
      p_pop = phase == 0 ? 0.2 : phase == 1 ? 0.9 : 0.5;
      if (r.chance(0.3)) limit = r.chance(0.3) ? depth : r.chance(0.3) ? 1 : 1 + int(r.below(uint64_t(depth)));
    }
    top.clk_i = 0;
    top.limit_i = limit;
    top.push_i = top.pop_i = 0;
    top.eval();
    const bool empty = model.empty(), full = int(model.size()) >= limit;
    m.check(top.count_o == model.size(), t,
            "count " + std::to_string(top.count_o) + ", model " + std::to_string(model.size()));
    m.check(bool(top.empty_o) == empty, t, "empty");
    m.check(bool(top.full_o) == full, t, "full");
    if (!empty) m.check(get(top.data_o) == model.front(), t, "head data differs from the model's");
    const bool pop = !empty && r.chance(p_pop);
    const bool push = (!full || pop) && r.chance(p_push);
    const Word data = random_word(r, width);
    top.pop_i = pop;
    top.push_i = push;
    put(top.data_i, data);
    top.eval();
    top.clk_i = 1;
    top.eval();
    if (pop) model.pop_front(), ++c.pops;
    if (push) model.push_back(data), ++c.pushes;
    c.full_ticks += full;
  }
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  const unit_bench::Args a = unit_bench::parse_args(argc, argv);
  VerilatedContext ctx;
  unit_bench::seed(ctx, a);
  Vpixel_fifo thesis{&ctx, "thesis"};
  Vpixel_fifo_small small{&ctx, "small"};
  Random r(a.seed);
  Mismatches m("fifo");
  const Counts ct = run(thesis, 32, 69, a.ticks, r, m);
  const Counts cs = run(small, 5, 8, a.ticks, r, m);
  return unit_bench::finish(ctx, a, m, "fifo",
                            std::to_string(a.ticks) + " ticks a build; 32 deep: " + std::to_string(ct.pushes) +
                                " pushes, " + std::to_string(ct.full_ticks) +
                                " ticks full; 5 deep: " + std::to_string(cs.pushes) + " pushes, " +
                                std::to_string(cs.full_ticks) + " ticks full");
}
