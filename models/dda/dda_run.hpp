// A span's pixels handed to a sink as one run (the span path,
// dda_span.hpp). A sink that takes runs says so (kTakesRuns) and has
// run(source); it gets the clocked path's pixels, and any other sink all
// of them, as DdaEmits one by one. A run source gives
// size() pixels along row y() from x_first() to x_last(), one per DDA clock
// from first_cycle() on (the clock each leaves the DDA, as DdaEmit::cycle),
// each from next() as a RunPixel: what the HAD reads, no registers; and
// whether every one of them is covered and opaque (covered_opaque()).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>

#include "common/types.hpp"
#include "dda/dda_emission.hpp"

namespace girtd {

struct RunPixel {
  Pixel pixel;
  bool covered;
};

template <typename Sink, typename = void>
struct TakesRuns : std::false_type {};
template <typename Sink>
struct TakesRuns<Sink, std::void_t<decltype(Sink::kTakesRuns)>> : std::bool_constant<Sink::kTakesRuns> {};

// A plain span's pixels (DdaEmission::emit_plain's values), stepping only
// the registers they read: R, G, B, T, Z, and the edges' only where one
// has a fringe (kFringe: `covered` reads D = 0). nf is T; where T does not
// change along the row (kVaryingT false), it is worked out once.
template <bool kFringe, bool kVaryingT>
class PlainRun {
 public:
  PlainRun(const DdaEmission::PlainFormat& f, const DdaRegisters& r, const std::array<int64_t, kEpCount>& step, int s,
           int64_t n, uint64_t first_cycle)
      : f_(f), x_(r.x), y_(r.y), s_(s), x_last_(r.x + static_cast<int>(s * (n - 1))), n_(n), first_cycle_(first_cycle) {
    for (int i = 0; i < kStepped; ++i) {
      v_[i] = r.v[i];
      step_[i] = step[i];
    }
    nf_ = f_.nf(v_[kEpT]);
  }
  int64_t size() const { return n_; }
  int y() const { return y_; }
  int x_first() const { return x_; }
  int x_last() const { return x_last_; }
  uint64_t first_cycle() const { return first_cycle_; }
  // Every pixel is inside the triangle, and opaque (nf = 1).
  bool covered_opaque() const { return !kFringe && !kVaryingT && nf_ == kNfOne; }
  RunPixel next() {
    RunPixel p;
    p.pixel = f_.outputs(x_, y_, v_.data());
    p.pixel.nf = kVaryingT ? f_.nf(v_[kEpT]) : nf_;
    p.covered = true;
    if constexpr (kFringe) p.covered = f_.covered(&v_[kEpD1]);
    x_ += s_;
    for (int i = 0; i < kStepped; ++i) v_[i] += step_[i];
    return p;
  }

 private:
  static_assert(kEpR == 0 && kEpZ == 4 && kEpD1 == 5, "R..Z then the edges: the stepped prefix");
  static constexpr int kStepped = kFringe ? kEpCount : kEpZ + 1;
  DdaEmission::PlainFormat f_;
  int x_, y_, s_, x_last_;
  int64_t n_;
  uint64_t first_cycle_;
  uint16_t nf_ = 0;
  std::array<int64_t, kStepped> v_{}, step_{};
};

// Any span's pixels as a run source: each as DdaEmission::emit() makes it.
class EmittedRun {
 public:
  EmittedRun(const DdaEmission& em, const DdaRegisters& r, const std::array<int64_t, kEpCount>& step, int s, int64_t n,
             uint64_t first_cycle)
      : em_(&em), r_(r), step_(&step), s_(s), x_first_(r.x), x_last_(r.x + static_cast<int>(s * (n - 1))), n_(n),
        first_cycle_(first_cycle) {}
  int64_t size() const { return n_; }
  int y() const { return r_.y; }
  int x_first() const { return x_first_; }
  int x_last() const { return x_last_; }
  uint64_t first_cycle() const { return first_cycle_; }
  bool covered_opaque() const { return false; }
  RunPixel next() {
    const DdaEmit e = em_->emit(r_, 0);
    r_.x += s_;
    for (int i = 0; i < kEpCount; ++i) r_.v[i] += (*step_)[i];
    return {e.pixel, e.covered};
  }

 private:
  const DdaEmission* em_;
  DdaRegisters r_;
  const std::array<int64_t, kEpCount>* step_;
  int s_, x_first_, x_last_;
  int64_t n_;
  uint64_t first_cycle_;
};

// Hands a plain span to a run sink through the PlainRun that fits it.
template <typename Sink>
[[gnu::always_inline]] inline void deliver_plain_run(const Sink& sink, const DdaEmission::PlainFormat& f, const DdaRegisters& r,
                       const std::array<int64_t, kEpCount>& step, int s, int64_t n, uint64_t first_cycle) {
  const bool fringe = f.soft_edges != 0, varying_t = step[kEpT] != 0;
  if (fringe) {
    if (varying_t) sink.run(PlainRun<true, true>(f, r, step, s, n, first_cycle));
    else sink.run(PlainRun<true, false>(f, r, step, s, n, first_cycle));
  } else {
    if (varying_t) sink.run(PlainRun<false, true>(f, r, step, s, n, first_cycle));
    else sink.run(PlainRun<false, false>(f, r, step, s, n, first_cycle));
  }
}

}  // namespace girtd
