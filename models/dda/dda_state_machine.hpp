// The DDA's clocked state machine (the state table is in models/dda/README.md),
// written once for both of DdaEngine's datapaths:
// - DdaDatapath, the specification: every clock one unit move or AUX
//   transfer, adders wrapping like the hardware's, the wrap detector's
//   registers beside them;
// - ExactDatapath, for a triangle that cannot wrap (exact_steps): plain adds,
//   and each emitting run, with the clocks that find and end it and the
//   one-clock states after it, taken as one span (dda_span.hpp) from the
//   registers at its first pixel.
// Header-only so that a caller's pixel sink is inlined (DdaEngine::run_inline).
#pragma once

#include <array>
#include <functional>
#include <stdexcept>
#include <type_traits>

#include "dda/dda_datapath.hpp"
#include "dda/dda_emission.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_span.hpp"

namespace girtd {

// Whether a sink or probe is there: a std::function may be empty, anything else is called.
template <typename F>
bool is_set(const F&) {
  return true;
}
template <typename... A>
bool is_set(const std::function<A...>& f) {
  return static_cast<bool>(f);
}
struct NoProbe {
  void operator()(const DdaClock&) const {}
};
inline bool is_set(const NoProbe&) { return false; }

template <typename Datapath, typename Sink, typename Probe>
DdaRunStats run_state_machine(const Params& params, const DdaParams& in, Datapath& dp, bool detect, const Sink& sink,
                              const Probe& probe) {
  constexpr bool kSpans = Datapath::kExact;  // spans need adds that cannot wrap
  if constexpr (kSpans) detect = false;        // nothing to detect
  const DdaEmission emission(params, in);
  const bool fix = params.walk_fix;
  const bool pipelined_compare = params.xy_compare_pipelined;
  const bool has_sink = is_set(sink), has_probe = is_set(probe);
  // The span path reads the live registers, and takes several clocks at once.
  if (kSpans && has_probe) throw std::logic_error("DDA: the span path takes no clock probe");

  bool d_tested = false;  // this clock read D1..D3 (wrapped ones are counted then)
  auto d_inside = [&](const DdaRegisters& r) {
    d_tested = true;
    return emission.d_inside(r);
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
      if (!emission.edge_inside(r, e)) return in.ep[e].dx < 0 ? -1 : (in.ep[e].dx > 0 || !fix ? +1 : 0);
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
  auto emitting = [](DdaState st) { return st == DdaState::kRight || st == DdaState::kLeft || st == DdaState::kRun; };
  // An emitting state's clock that ends its run: at a pixel it cannot emit,
  // or at the last pixel before the X limit (after emitting it).
  auto run_ends = [&](DdaState now) {
    if (now == DdaState::kLeft) {
      dp.step_y();
      state = end_run(DdaState::kCheck);
    } else {
      dp.restore();
      state = end_run(now == DdaState::kRight ? DdaState::kLStep : DdaState::kYStep);
    }
  };
  auto lstep = [&](int x) {
    if (x > in.xmin) {
      dp.step_x(-1);
      state = DdaState::kLeft;
    } else {
      dp.step_y();
      state = end_run(DdaState::kCheck);
    }
  };
  // CHECK or WALK at an inside pixel: AUX keeps it, and the run starts.
  auto run_found = [&](DdaState now) {
    dp.save();
    state = now == DdaState::kCheck ? DdaState::kRight : DdaState::kRun;
  };
  auto ystep = [&] {
    dp.step_y();
    state = DdaState::kCheck;
  };
  const uint64_t width = static_cast<uint64_t>(in.xmax - in.xmin + 1);
  const uint64_t rows = static_cast<uint64_t>(in.ymax - in.y0 + 2);
  const uint64_t clock_bound = (3 * width + 16) * rows + 16;
  const uint64_t latency = static_cast<uint64_t>(params.output_latency_clocks);

  DdaRegisters exact;  // this clock's registers had no adder wrapped (when detecting)
  for (;;) {
    // This clock's pixel, before the clock's op. The span datapath's ops
    // come after every read of it in a clock, so there it need not be copied.
    std::conditional_t<kSpans, const DdaRegisters&, const DdaRegisters> r = dp.pix();
    const DdaState now = state;
    // An emitting state (RIGHT, LEFT, RUN), as one span: a clock per
    // inside pixel that emits and steps on, then the clock that ends the
    // run (the last pixel's own at the X limit, else the outside pixel's),
    // then the one-clock states that follow it (WAIT, LSTEP, YSTEP).
    // Before it, the clock that finds the run (CHECK or WALK at an inside pixel).
    if constexpr (kSpans) {
      DdaState run_state = now;
      uint64_t found = 0;  // 1: this iteration began with the finding clock
      if (((now == DdaState::kCheck && r.y <= in.ymax) || now == DdaState::kWalk) && inside(r)) {
        found = 1;
        ++st.per_state[static_cast<int>(now)];
        first_check = false;
        run_found(now);
        run_state = state;
      }
      if (emitting(run_state)) {
        const int s = run_state == DdaState::kRight ? +1 : run_state == DdaState::kLeft ? -1 : walk_dir;
        const int64_t n = inside(r) ? span_length(emission, in, r, s) : 0;
        const bool at_limit = n > 0 && r.x + s * (n - 1) == (s > 0 ? in.xmax : in.xmin);
        if (n > 0) {
          emit_span(emission, dp.with_outputs(), s, dp.toward(s), n, st.cycles + found + latency, has_sink, sink, saturations);
          // The clock that ends the run is at its last pixel (at the X limit)
          // or the outside one after it. Only LEFT goes on from there (to
          // YSTEP); RIGHT and RUN end by restoring AUX (run_ends).
          if (run_state == DdaState::kLeft) dp.step_x_by(s, at_limit ? n - 1 : n);
        }
        uint64_t clocks = static_cast<uint64_t>(at_limit ? n : n + 1);
        st.emitted += static_cast<uint64_t>(n);
        st.per_state[static_cast<int>(run_state)] += clocks;
        clocks += found;
        run_ends(run_state);
        for (;; ++clocks) {
          const DdaState next = state;
          if (next == DdaState::kWait) state = after_wait;
          else if (next == DdaState::kLStep) lstep(dp.pix().x);
          else if (next == DdaState::kYStep) ystep();
          else break;
          ++st.per_state[static_cast<int>(next)];
        }
        st.cycles += clocks;
        st.span_clocks += clocks;
        continue;
      }
    }
    if (detect) exact = dp.exact();
    d_tested = false;
    bool emit = false, done = false;
    auto emit_here = [&] {
      emit = true;
      for (int i : kOutputEps) {
        saturations[i] += emission.counts_saturation(i, r.v[i]);
        wraps[i] += detect && r.v[i] != exact.v[i];
      }
      if (has_sink) sink(emission.emit(r, st.cycles + latency));
    };

    switch (now) {
      case DdaState::kCheck:
        if (r.y > in.ymax) {
          done = true;
        } else if (inside(r)) {
          run_found(now);
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
          run_found(now);
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
        run_ends(now);
        break;

      case DdaState::kLStep:
        lstep(r.x);
        break;

      case DdaState::kLeft:
        if (inside(r)) {
          emit_here();
          if (r.x > in.xmin) {
            dp.step_x(-1);
            break;
          }
        }
        run_ends(now);
        break;

      case DdaState::kRun:
        if (inside(r)) {
          emit_here();
          if (can_step(r, walk_dir)) {
            dp.step_x(walk_dir);
            break;
          }
        }
        run_ends(now);
        break;

      case DdaState::kYStep:
        ystep();
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
    if (has_probe) probe(DdaClock{now, r.x, r.y, emit});
    if (done) break;
    if (st.cycles > clock_bound) throw std::logic_error("DDA: traversal did not terminate");
  }
  st.triangles = 1;
  st.undetected = !detect;
  st.numerics = run_numerics(in, wraps, saturations);
  return st;
}

// DdaEngine's choice of datapath for one triangle.
template <typename Sink, typename Probe>
DdaRunStats DdaEngine::run_any(const DdaParams& in, const Sink& sink, const Probe& probe) const {
  if (spans_ && !is_set(probe) && exact_steps(params_, in)) {
    ExactDatapath dp(params_, in);
    return run_state_machine(params_, in, dp, false, sink, probe);
  }
  // The wrap detector's registers, unless simulator pruning knows nothing can wrap.
  const bool detect = !skip_unreachable_wraps_ || may_wrap(params_, in);
  DdaDatapath dp(params_, in, detect);
  return run_state_machine(params_, in, dp, detect, sink, probe);
}

template <typename Sink>
DdaRunStats DdaEngine::run_inline(const DdaParams& in, const Sink& sink) const {
  return run_any(in, sink, NoProbe{});
}

}  // namespace girtd
