// The golden DDA (§4, fig. 4.2 / the thesis' DDApix) as a clocked state
// machine: every clock does one unit move (X++, X--, Y++) or one AUX
// transfer, decided from the registers as they stand. The state table is in
// models/dda/README.md. Bit-exact specification for hw/dda.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "common/types.hpp"
#include "config/params.hpp"
#include "dda/dda_params.hpp"
#include "dda/ep_numerics.hpp"

namespace girtd {

enum class DdaState : uint8_t { kCheck, kRight, kLStep, kLeft, kWalk, kRun, kYStep, kWait, kCount };
inline constexpr const char* kDdaStateNames[] = {"CHECK", "RIGHT", "LSTEP", "LEFT",
                                                 "WALK",  "RUN",   "YSTEP", "WAIT"};

struct DdaEmit {
  Pixel pixel;
  uint64_t cycle = 0;                     // clock the pixel leaves the DDA (state clock + latency)
  std::array<int64_t, kEpCount> raw{};    // EP registers at emission, before output stages
  bool covered = false;                   // inside the triangle: not in a fringe, not on a soft edge
};

// One clock as seen from outside: the state, the pixel position, whether it emitted.
struct DdaClock {
  DdaState state;
  int x, y;
  bool emitted;
};

struct DdaRunStats {
  uint64_t cycles = 0;
  uint64_t emitted = 0;
  uint64_t triangles = 0;  // runs summed in (1 for one run)
  EpNumerics numerics;     // wraps and output saturations (clamps: the preparer's)
  std::array<uint64_t, static_cast<int>(DdaState::kCount)> per_state{};
  bool ended_at_limit = false;  // DDApix as written ended a walk at Xmin/Xmax
  // Simulator, not hardware: runs without the wrap detector's registers
  // (skip_unreachable_wraps: nothing could wrap). Not in report.json's counts.
  uint64_t undetected = 0;
  // Simulator, not hardware: clocks the span path computed as whole spans
  // (compute_spans). Not in report.json's counts.
  uint64_t span_clocks = 0;
  uint64_t wasted() const { return cycles - emitted; }
};

class DdaEngine {
 public:
  using PixelSink = std::function<void(const DdaEmit&)>;
  using ClockProbe = std::function<void(const DdaClock&)>;

  explicit DdaEngine(const Params& p) : params_(p) {}
  // Simulator pruning: no wrap-detector registers for a triangle that cannot
  // wrap (may_wrap); its numerics are the same.
  void skip_unreachable_wraps(bool skip) { skip_unreachable_wraps_ = skip; }
  // Simulator pruning: a triangle that cannot wrap (exact_steps) runs with
  // plain adds, without the wrap detector's registers (it counts as
  // `undetected`, whatever skip_unreachable_wraps says), and each emitting
  // run computed as one span (dda_state_machine.hpp); same pixels, clocks
  // and counts. Not with a probe.
  void compute_spans(bool on) { spans_ = on; }

  DdaRunStats run(const DdaParams& in, const PixelSink& sink, const ClockProbe& probe = {}) const;
  // The same with the sink inlined: include dda/dda_state_machine.hpp.
  template <typename Sink>
  DdaRunStats run_inline(const DdaParams& in, const Sink& sink) const;

 private:
  template <typename Sink, typename Probe>
  DdaRunStats run_any(const DdaParams& in, const Sink& sink, const Probe& probe) const;

  const Params& params_;
  bool skip_unreachable_wraps_ = false;
  bool spans_ = false;
};

}  // namespace girtd
