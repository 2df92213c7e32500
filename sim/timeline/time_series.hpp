// Modeled time cut into equal bins, for the report page's timelines: a
// stage's busy, starved and blocked seconds in each bin, or a FIFO's largest
// occupancy. Adaptive: bins start at 1 us and, when a run outgrows
// kMaxBins, neighbours merge and the bin doubles, so a run longer than
// kMaxBins us keeps between kMaxBins / 2 and kMaxBins bins (a 1 s run: bins
// of 1.024 ms). Plain C++
// (the report reads it). Its cost is measured by `girtd bench --speed`.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "timeline/series_switch.hpp"

namespace girtd {

template <size_t Channels>
class TimeSeries {
 public:
  static constexpr size_t kMaxBins = 1024;
  using Bin = std::array<double, Channels>;

  // `peaks`: the channels hold maxima (two bins merge to the larger), else
  // seconds (two bins merge to their sum).
  // When series are recorded, all kMaxBins bins are allocated and written
  // here, as the model is built, before the run: a bin first touched during
  // it would cost a page fault, a few us on a VM, more than a short run's
  // whole series. `girtd bench --speed` measures both: the run (`wall_s`)
  // and the process, where these faults now fall.
  explicit TimeSeries(bool peaks = false) : peaks_(peaks) {
    if (!record_series()) return;
    bins_.resize(kMaxBins);
    bins_.clear();
  }

  double bin_s() const { return bin_s_; }
  const std::vector<Bin>& bins() const { return bins_; }

  // Spreads the span [t0, t1) of channel `c` over the bins it covers; with
  // `weight` w, w seconds per second of the span (a share of it).
  void add_span(size_t c, double t0, double t1, double weight = 1.0) {
    if (t1 <= t0) return;
    grow_to(t1);
    for (size_t i = index(t0); t0 < t1; ++i) {
      const double end = std::min(t1, double(i + 1) * bin_s_);
      bins_[std::min(i, bins_.size() - 1)][c] += (end - t0) * weight;
      t0 = end;
    }
  }
  // `value` held by channel `c` over [t0, t1]: every bin it touches keeps
  // the largest value seen in it.
  void note_max(size_t c, double t0, double t1, double value) {
    grow_to(t1);
    for (size_t i = index(t0), last = index(t1); i <= last; ++i) bins_[i][c] = std::max(bins_[i][c], value);
  }

 private:
  size_t index(double t) const { return std::min(size_t(t / bin_s_), bins_.empty() ? 0 : bins_.size() - 1); }
  // Enough bins to hold time t (inclusive), coarsening as needed.
  void grow_to(double t) {
    while (t >= double(kMaxBins) * bin_s_) coarsen();
    const size_t need = size_t(t / bin_s_) + 1;
    if (bins_.size() < need) bins_.resize(need, Bin{});
  }
  void coarsen() {  // in place: bin i takes 2i and 2i + 1, both at or after it
    const size_t merged = (bins_.size() + 1) / 2;
    for (size_t i = 0; i < merged; ++i) {
      Bin m = bins_[2 * i];
      if (2 * i + 1 < bins_.size())
        for (size_t c = 0; c < Channels; ++c)
          m[c] = peaks_ ? std::max(m[c], bins_[2 * i + 1][c]) : m[c] + bins_[2 * i + 1][c];
      bins_[i] = m;
    }
    bins_.resize(merged);
    bin_s_ *= 2;
  }

  bool peaks_;
  double bin_s_ = 1e-6;
  std::vector<Bin> bins_;
};

// A stage: starved, busy and blocked seconds per bin (StageState's order).
using StageSeries = TimeSeries<3>;
// A FIFO: its largest occupancy per bin.
using FifoSeries = TimeSeries<1>;

}  // namespace girtd
