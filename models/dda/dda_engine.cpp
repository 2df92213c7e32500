#include "dda/dda_engine.hpp"

#include <stdexcept>

#include "common/fixed_point.hpp"
#include "dda/dda_datapath.hpp"
#include "dda/nf_unit.hpp"

namespace girtd {

DdaRunStats DdaEngine::run(const DdaParams& in, const PixelSink& sink, const ClockProbe& probe) const {
  // The wrap detector's registers, unless simulator pruning knows nothing can wrap.
  const bool detect = !skip_unreachable_wraps_ || may_wrap(params_, in);
  DdaDatapath dp(params_, in, detect);
  // One Norm unit per edge: an interior edge's (edge flags) has no fringe.
  auto norm_unit = [&](int e) {
    return NormUnit(params_.ep_d, params_.norm_frac_bits, (in.hard_edges >> e) & 1 ? 0.0 : in.q);
  };
  const std::array<NormUnit, 3> norm{norm_unit(0), norm_unit(1), norm_unit(2)};
  auto edge_inside = [&](const DdaRegisters& r, int ep) { return norm[ep - kEpD1].inside(r.v[ep]); };
  const bool fix = params_.walk_fix;
  const bool pipelined_compare = params_.xy_compare_pipelined;

  bool d_tested = false;  // this clock read D1..D3 (wrapped ones are counted then)
  auto d_inside = [&](const DdaRegisters& r) {
    d_tested = true;
    return edge_inside(r, kEpD1) && edge_inside(r, kEpD2) && edge_inside(r, kEpD3);
  };
  auto in_limits = [&](const DdaRegisters& r) { return r.x >= in.xmin && r.x <= in.xmax; };
  auto inside = [&](const DdaRegisters& r) { return in_limits(r) && d_inside(r); };
  // DIR (§4.2.4): the sign of D'x of the first edge whose Norm is 0; +1 = right.
  // 0 = no horizontal way in (the edge is horizontal).
  auto dir = [&](const DdaRegisters& r) -> int {
    if (r.x < in.xmin) return +1;
    if (r.x > in.xmax) return -1;
    d_tested = true;
    for (int e = kEpD1; e <= kEpD3; ++e)
      if (!edge_inside(r, e)) return in.ep[e].dx < 0 ? -1 : (in.ep[e].dx > 0 || !fix ? +1 : 0);
    return +1;
  };
  auto can_step = [&](const DdaRegisters& r, int s) { return s > 0 ? r.x < in.xmax : r.x > in.xmin; };

  DdaRunStats st;
  std::array<uint64_t, kEpCount> wraps{}, saturations{};
  DdaState state = DdaState::kCheck, after_wait = DdaState::kCheck;
  int walk_dir = +1;
  bool first_check = true;
  // A run's end costs one more clock when the X/Y compare is pipelined (TTL).
  auto end_run = [&](DdaState next) {
    if (!pipelined_compare) return next;
    after_wait = next;
    return DdaState::kWait;
  };
  const uint64_t width = static_cast<uint64_t>(in.xmax - in.xmin + 1);
  const uint64_t rows = static_cast<uint64_t>(in.ymax - in.y0 + 2);
  const uint64_t clock_bound = (3 * width + 16) * rows + 16;

  DdaRegisters exact;  // this clock's registers had no adder wrapped (when detecting)
  for (;;) {
    const DdaRegisters r = dp.pix();  // this clock's pixel, before the clock's op
    if (detect) exact = dp.exact();
    const DdaState now = state;
    d_tested = false;
    bool emit = false, done = false;
    auto emit_here = [&] {
      emit = true;
      for (int i : {kEpR, kEpG, kEpB, kEpT, kEpZ}) {
        // T's 1.0 is 256, carried out as 255 by design (models/dda/README.md): not a clip.
        const bool t_one = i == kEpT && (r.v[i] >> dp.format(i).frac_bits) == 256;
        saturations[i] += !t_one && output_saturates(r.v[i], dp.format(i));
        wraps[i] += detect && r.v[i] != exact.v[i];
      }
      if (!sink) return;
      DdaEmit e;
      e.raw = r.v;
      e.cycle = st.cycles + static_cast<uint64_t>(params_.output_latency_clocks);
      const int t = t_operand(saturate_output(r.v[kEpT], params_.ep_t));
      const int n1 = norm[0].norm(r.v[kEpD1]), n2 = norm[1].norm(r.v[kEpD2]), n3 = norm[2].norm(r.v[kEpD3]);
      e.pixel = output_pixel(r, params_, compute_nf(n1, n2, n3, t, params_.prom_frac_bits));
      // Covered: inside every hard edge, strictly inside every soft one (a
      // pixel on a silhouette is on the boundary, not a triangle's own).
      e.covered = n1 == kNfOne && n2 == kNfOne && n3 == kNfOne;
      for (int i = 0; i < 3; ++i)
        if (in.q > 0 && !((in.hard_edges >> i) & 1) && r.v[kEpD1 + i] == 0) e.covered = false;
      sink(e);
    };

    switch (now) {
      case DdaState::kCheck:
        if (r.y > in.ymax) {
          done = true;
        } else if (inside(r)) {
          dp.save();
          state = DdaState::kRight;
        } else if (!fix && first_check) {  // DDApix: an outside start skips its row
          dp.step_y();
        } else {
          walk_dir = dir(r);
          if (walk_dir == 0) {
            dp.step_y();
          } else if (!can_step(r, walk_dir)) {
            if (fix) dp.step_y();
            else done = st.ended_at_limit = true;
          } else {
            dp.step_x(walk_dir);
            state = DdaState::kWalk;
          }
        }
        first_check = false;
        break;

      case DdaState::kWalk:
        if (inside(r)) {
          dp.save();
          state = DdaState::kRun;
        } else if (fix && dir(r) != walk_dir) {  // walked across a row with no pixel
          dp.step_y();
          state = DdaState::kCheck;
        } else if (!can_step(r, walk_dir)) {
          if (fix) {
            dp.step_y();
            state = DdaState::kCheck;
          } else {
            done = st.ended_at_limit = true;
          }
        } else {
          dp.step_x(walk_dir);
        }
        break;

      case DdaState::kRight:
        if (inside(r)) {
          emit_here();
          if (r.x < in.xmax) {
            dp.step_x(+1);
            break;
          }
        }
        dp.restore();
        state = end_run(DdaState::kLStep);
        break;

      case DdaState::kLStep:
        if (r.x > in.xmin) {
          dp.step_x(-1);
          state = DdaState::kLeft;
        } else {
          dp.step_y();
          state = end_run(DdaState::kCheck);
        }
        break;

      case DdaState::kLeft:
        if (inside(r)) {
          emit_here();
          if (r.x > in.xmin) {
            dp.step_x(-1);
            break;
          }
        }
        dp.step_y();
        state = end_run(DdaState::kCheck);
        break;

      case DdaState::kRun:
        if (inside(r)) {
          emit_here();
          if (can_step(r, walk_dir)) {
            dp.step_x(walk_dir);
            break;
          }
        }
        dp.restore();
        state = end_run(DdaState::kYStep);
        break;

      case DdaState::kYStep:
        dp.step_y();
        state = DdaState::kCheck;
        break;

      case DdaState::kWait:
        state = after_wait;
        break;

      case DdaState::kCount:
        throw std::logic_error("DDA: invalid state");
    }

    // A wrapped D read this clock can put the pixel on the wrong side of an edge.
    if (d_tested && detect)
      for (int e = kEpD1; e <= kEpD3; ++e) wraps[e] += r.v[e] != exact.v[e];
    ++st.cycles;
    st.emitted += emit;
    ++st.per_state[static_cast<int>(now)];
    if (probe) probe(DdaClock{now, r.x, r.y, emit});
    if (done) break;
    if (st.cycles > clock_bound) throw std::logic_error("DDA: traversal did not terminate");
  }
  st.triangles = 1;
  st.undetected = !detect;
  st.numerics = run_numerics(in, wraps, saturations);
  return st;
}

}  // namespace girtd
