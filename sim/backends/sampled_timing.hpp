// Sampled timing (SMARTS-style) for the approx back end: the accuracy
// command's cheaper estimator `approx_sampled_<rate>`. Of every k =
// round(1/rate) triangles in the stream, the first is timed (measured), the
// last is simulated without being measured (warm-up: the measured one finds
// the FIFO and the cache page as a full run would), and the others are
// skipped: neither drawn nor simulated, the DDA taken for an estimate
// instead. Unlike SMARTS there is no functional warming: a skipped triangle
// writes no Z, so measured ones see fewer Z rejections than in a full run
// (one source of the error `girtd accuracy` measures). The estimate is a
// ratio estimator on the triangle's pixel box (measured ticks per box
// pixel), charged with the ratio as it stands; the 99.7 % interval (3 sigma)
// is that of the final ratio. A skipped triangle draws nothing, so the frame
// is incomplete: render warns. Not a hardware option: no config key, no
// effect on golden or rtl.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include "dda/dda_params.hpp"

namespace girtd {

struct SamplingStats {
  double rate = 1;                // 1 / k: the fraction of triangles measured
  uint64_t measured = 0, warmed = 0, skipped = 0;  // triangles
  double skipped_ticks = 0;       // the estimate the skipped ones were charged
  double ci_half_ticks = 0;       // 99.7 % confidence half-width of that estimate
};

class TriangleSampler {
 public:
  enum class Role { kMeasure, kWarm, kSkip };
  explicit TriangleSampler(double rate) : period_(std::max<uint64_t>(1, uint64_t(std::llround(1 / rate)))) {
    s_.rate = 1.0 / double(period_);  // the fraction actually measured
  }
  Role next() {
    const uint64_t phase = index_++ % period_;
    if (phase == 0) return Role::kMeasure;
    return phase == period_ - 1 ? Role::kWarm : Role::kSkip;
  }
  static double weight(const DdaParams& d) {
    return double(std::max(0, d.xmax - d.xmin + 1)) * double(std::max(0, d.ymax - d.y0 + 1)) + 1;
  }
  void measured(const DdaParams& d, uint64_t ticks) {
    const double w = weight(d), t = double(ticks);
    ++s_.measured;
    sum_w_ += w, sum_t_ += t, sum_ww_ += w * w, sum_tt_ += t * t, sum_tw_ += t * w;
  }
  void warmed() { ++s_.warmed; }
  // The ticks to charge a skipped triangle (the running ratio).
  uint64_t skip(const DdaParams& d) {
    const double w = weight(d);
    ++s_.skipped;
    skipped_w_ += w;
    const double est = sum_w_ > 0 ? sum_t_ / sum_w_ * w : 0;
    s_.skipped_ticks += est;
    return uint64_t(std::llround(est));
  }
  SamplingStats stats() const {
    SamplingStats s = s_;
    const double n = double(s.measured);
    if (n >= 2 && sum_w_ > 0) {
      // Var(R) ~ sum (t - R w)^2 / (n - 1) / (n mean_w^2)
      const double r = sum_t_ / sum_w_, mean_w = sum_w_ / n;
      const double ss = std::max(0.0, sum_tt_ - 2 * r * sum_tw_ + r * r * sum_ww_) / (n - 1);
      s.ci_half_ticks = 3 * skipped_w_ * std::sqrt(ss / n) / mean_w;
    }
    return s;
  }

 private:
  uint64_t period_, index_ = 0;
  SamplingStats s_;
  double sum_w_ = 0, sum_t_ = 0, sum_ww_ = 0, sum_tt_ = 0, sum_tw_ = 0, skipped_w_ = 0;
};

}  // namespace girtd
