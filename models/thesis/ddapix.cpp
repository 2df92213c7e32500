#include "thesis/ddapix.hpp"

#include "common/fixed_point.hpp"
#include "dda/dda_datapath.hpp"

namespace girtd {
namespace {

constexpr int64_t kOne16 = int64_t{1} << 16;  // 1.0 in the 16.16 D and T registers

// Folds a Norm value (0x100 = 1, else a byte) into the running nf like NF's
// `or ch,ch` branches: the first factor below 1 is taken, later ones multiply.
void fold(int& nf, int byte) { nf = nf >= 0x100 ? byte : (byte * nf) >> 8; }

}  // namespace

int thesis_nf(int64_t d1, int64_t d2, int64_t d3, int64_t t) {
  int nf = 0x100;
  for (int64_t d : {d1, d2, d3}) {
    const int64_t hi = d >> 16;  // the register's high word: the integer part
    if (hi + 1 < 0) return 0;    // D < -1
    if (hi + 1 == 0) fold(nf, static_cast<int>((d >> 8) & 0xFF));  // -1 <= D < 0: D + 1
  }
  const int64_t t_hi = t >> 16;
  if (t_hi < 0) return 0;
  if (t_hi == 0) fold(nf, static_cast<int>((t >> 8) & 0xFF));  // T >= 1 counts as 1
  return nf;
}

DdaRunStats DdaPix::run(const DdaParams& in, const DdaEngine::PixelSink& sink) const {
  DdaDatapath dp(params_, in, false);  // the appendix program's numerics are its own: no wrap detector
  const int64_t threshold = inside_ == ThesisInside::kProgram ? -kOne16 : 0;
  DdaRunStats st;

  auto interno = [&] {
    const DdaRegisters& r = dp.pix();
    return r.v[kEpD1] >= threshold && r.v[kEpD2] >= threshold && r.v[kEpD3] >= threshold;
  };
  // DIR: the first of D1, D2 below the threshold, else D3; left when its D'x < 0.
  auto dir_left = [&] {
    const DdaRegisters& r = dp.pix();
    const int e = r.v[kEpD1] < threshold ? kEpD1 : r.v[kEpD2] < threshold ? kEpD2 : kEpD3;
    return in.ep[e].dx < 0;
  };
  auto clock = [&](DdaState s) { ++st.cycles, ++st.per_state[static_cast<int>(s)]; };
  auto inc_x = [&](DdaState s) { dp.step_x(+1), clock(s); };
  auto dec_x = [&](DdaState s) { dp.step_x(-1), clock(s); };
  auto save = [&] { dp.save(), clock(DdaState::kCheck); };
  auto restore = [&](DdaState s) { dp.restore(), clock(s); };
  auto atu_dsp = [&] {
    const DdaRegisters& r = dp.pix();
    ++st.emitted;
    if (!sink) return;
    DdaEmit e;
    e.raw = r.v;
    e.cycle = st.cycles + static_cast<uint64_t>(params_.output_latency_clocks);
    e.pixel = output_pixel(r, params_, thesis_nf(r.v[kEpD1], r.v[kEpD2], r.v[kEpD3], r.v[kEpT]));
    sink(e);
  };
  // lb1: the two half-rows around the current pixel.
  auto row = [&] {
    save();
    do {
      atu_dsp();
      inc_x(DdaState::kRight);
    } while (dp.pix().x <= in.xmax && interno());
    restore(DdaState::kRight);
    for (;;) {
      dec_x(DdaState::kLeft);
      if (dp.pix().x < in.xmin || !interno()) break;
      atu_dsp();
    }
  };

  if (interno()) row();
  for (;;) {  // lb2
    dp.step_y(), clock(DdaState::kYStep);
    if (dp.pix().y > in.ymax) break;
    if (interno()) {
      row();
      continue;
    }
    const bool left = dir_left();
    const int step = left ? -1 : +1;
    auto past_limit = [&] { return left ? dp.pix().x < in.xmin : dp.pix().x > in.xmax; };
    bool ended = false;
    do {
      dp.step_x(step), clock(DdaState::kWalk);
      if (past_limit()) {
        ended = true;
        break;
      }
    } while (!interno());
    if (ended) {
      st.ended_at_limit = true;
      break;  // fim
    }
    save();
    do {
      atu_dsp();
      dp.step_x(step), clock(DdaState::kRun);
    } while (!past_limit() && interno());
    restore(DdaState::kRun);
  }
  st.triangles = 1;
  st.numerics = run_numerics(in, {}, {});  // the appendix program's registers are its own: not counted
  return st;
}

}  // namespace girtd
