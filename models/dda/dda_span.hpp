// The span path of the state machine (dda_state_machine.hpp): for a
// triangle whose registers cannot wrap (exact_steps), every register is
// linear along a row, so an emitting run's length follows from the edge
// registers at its first pixel, and whether an output clips anywhere in it
// from its two ends (an output's unclipped values are one interval).
// The clocked path stays the specification; CTest cross-checks the two.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "dda/dda_emission.hpp"
#include "dda/dda_run.hpp"

namespace girtd {

// floor(a / b) for 0 <= a, 0 < b, where the quotient is below a run's
// width and k b <= a + b < 2^63 (register values that cannot wrap): through
// a double division, much faster than a 64-bit integer one, whose estimate
// is then off by at most one, corrected by one step either way.
inline int64_t whole_quotient(int64_t a, int64_t b) {
  int64_t k = static_cast<int64_t>(static_cast<double>(a) / static_cast<double>(b));
  if (k * b > a) --k;
  else if ((k + 1) * b <= a) ++k;
  return k;
}

// Pixels from `r` (inside) onward in direction `s` that are inside: within
// the X limits and on the inside of every edge.
inline int64_t span_length(const DdaEmission& em, const DdaParams& in, const DdaRegisters& r, int s) {
  int64_t n = s > 0 ? in.xmax - r.x + 1 : r.x - in.xmin + 1;
  for (int e = kEpD1; e <= kEpD3; ++e) {
    const int64_t step = s * in.ep[e].dx;
    if (step >= 0) continue;
    // Inside while D + k step >= the lowest inside value: k <= room / -step.
    const int64_t room = r.v[e] - em.lowest_inside(e), down = -step;
    if (room < down * (n - 1)) n = whole_quotient(room, down) + 1;
  }
  return n;
}

// The span's n pixels from `r`, one per clock from `first_cycle`, to the
// sink (if `emit`; as one run to a sink that takes runs), and its clipped
// outputs counted as the clocked path counts them. Where both ends are
// plain (DdaEmission::plain_span), so is every pixel between: nothing
// clips, and each pixel is emit_plain's.
template <typename Sink>
[[gnu::always_inline]] inline void emit_span(const DdaEmission& em, const DdaRegisters& r, int s, const std::array<int64_t, kEpCount>& step, int64_t n,
               uint64_t first_cycle, bool emit, const Sink& sink, std::array<uint64_t, kEpCount>& saturations) {
  const int64_t last = n - 1;  // steps from the first pixel to the last
  const bool plain = em.plain_span(r.v, step, last);
  if (!plain) {
    for (int i : kOutputEps) {  // pixel by pixel only for an EP that clips at an end
      if (!output_saturates(r.v[i], em.format(i)) && !output_saturates(r.v[i] + last * step[i], em.format(i))) continue;
      int64_t v = r.v[i];
      for (int64_t k = 0; k < n; ++k, v += step[i]) saturations[i] += em.counts_saturation(i, v);
    }
  }
  if (!emit) return;
  if constexpr (TakesRuns<Sink>::value) {
    if (plain) deliver_plain_run(sink, em.plain_format(), r, step, s, n, first_cycle);
    else sink.run(EmittedRun(em, r, step, s, n, first_cycle));
    return;
  }
  const DdaEmission::PlainFormat& f = em.plain_format();
  DdaRegisters p = r;
  for (int64_t k = 0; k < n; ++k) {
    const uint64_t cycle = first_cycle + static_cast<uint64_t>(k);
    sink(plain ? DdaEmission::emit_plain(f, p, cycle) : em.emit(p, cycle));
    p.x += s;
    for (int i = 0; i < kEpCount; ++i) p.v[i] += step[i];
  }
}

}  // namespace girtd
