// The approx back end: the golden DDA and HAD decide every pixel; the
// timing model decides when (its error against the RTL is measured by
// `girtd bench`, not assumed).
#include "backends/approx_backend.hpp"

#include <optional>
#include <vector>

#include "backends/golden_backend.hpp"
#include "backends/had_backend.hpp"
#include "backends/model_series.hpp"
#include "timeline/series_switch.hpp"
#include "dda/dda_state_machine.hpp"
#include "dda/dda_timing.hpp"

namespace girtd {
namespace {

class ApproxBackend : public HadBackend, public ModeledTime {
 public:
  ApproxBackend(const Params& p, std::optional<double> sample_rate)
      : HadBackend(p), period_ticks_(static_cast<uint64_t>(p.ticks(p.dda_clock_ns))), dda_(p), timing_(p) {
    if (sample_rate) sampler_.emplace(*sample_rate);
    if (record_series()) series_.emplace(p, timing_);
  }
  void prune(const PrunePlan& plan) override {
    dda_.skip_unreachable_wraps(plan.unreachable_wraps);
    dda_.compute_spans(plan.dda_spans);
  }
  void begin(const FrameSource& input) override { require_pipeline_input(input); }
  ModeledTime* modeled_time() override { return this; }
  uint64_t ready_tick() override { return timing_.dda_ready_tick(); }
  void idle_until(uint64_t tick) override { timing_.idle_until(tick); }
  void begin_frame(const FrameSettings& s) override {
    HadBackend::begin_frame(s);
    timing_.begin_frame();
    if (series_) series_->begin_frame();
  }
  void draw(const DdaParams& d) override {
    if (!sampler_) return simulate(d);
    const uint64_t start = timing_.dda_ready_tick();
    switch (sampler_->next()) {
      case TriangleSampler::Role::kMeasure:
        simulate(d);
        sampler_->measured(d, timing_.dda_ready_tick() - start);
        break;
      case TriangleSampler::Role::kWarm:
        simulate(d);
        sampler_->warmed();
        break;
      case TriangleSampler::Role::kSkip:
        // in whole DDA clocks, as a measured triangle takes
        timing_.skip_triangle((sampler_->skip(d) + period_ticks_ / 2) / period_ticks_ * period_ticks_);
        break;
    }
  }
  // The HAD and the timing model as the DDA's sink: pixel by pixel, or a
  // span's pixels as one run (one clock each from its first; the heat map
  // takes the run's ends).
  struct Sink {
    static constexpr bool kTakesRuns = true;
    ApproxBackend& e;
    int layer;
    void operator()(const DdaEmit& px) const {
      e.timing_.pixel({px.cycle, px.pixel.x, px.pixel.y, e.had_.update(px.pixel, layer, px.covered)});
      if (e.series_) e.series_->pixel(px.pixel.x, px.pixel.y);
    }
    template <typename Run>
    void run(const Run& pixels) const {
      uint64_t cycle = pixels.first_cycle();
      BackendTimingModel& timing = e.timing_;
      e.had_.update_run(pixels, layer,
                        [&](int x, int y, HadOutcome o) { timing.pixel({cycle++, x, y, o}); });
      if (e.series_) e.series_->run(pixels.y(), pixels.x_first(), pixels.x_last());
    }
  };
  void simulate(const DdaParams& d) {
    timing_.begin_triangle();
    const DdaRunStats st = dda_.run_inline(d, Sink{*this, d.layer});
    timing_.end_triangle(st.cycles);
    if (series_) series_->end_triangle(st.cycles, st.emitted);
    accumulate(r_.dda, st);
    ++r_.triangles_drawn;
    r_.pixels_generated += st.emitted;
  }
  void drain() override { timing_.drain(); }
  void end_frame() override {
    timing_.end_frame();
    HadBackend::end_frame();
  }
  uint64_t now_tick() const override { return timing_.timing().ticks; }
  BackendCounters counters() const override {
    const BackendTiming& t = timing_.timing();
    return {t.dda_clocks, t.dda_wait_clocks * period_ticks_, t.had_busy_ticks};
  }
  BackendResult result() const override {
    BackendResult r = r_;
    const BackendTiming& t = timing_.timing();
    r.ticks = t.ticks;
    r.had = had_.counts();
    r.dda_wait_ticks = t.dda_wait_clocks * period_ticks_;
    r.page_misses = t.page_misses;
    r.had_busy_ticks = t.had_busy_ticks;
    r.had_vram_wait_ticks = t.had_vram_wait_ticks;
    r.fifo_max = static_cast<uint64_t>(t.fifo_max);
    if (sampler_) r.sampling = sampler_->stats();
    return r;
  }
  std::optional<ScreenMaps> screen_maps() const override {
    if (!series_) return std::nullopt;
    return series_->maps();
  }
  std::optional<FifoSeries> fifo_levels(uint64_t end) const override {
    if (!series_) return std::nullopt;
    return series_->fifo(end);
  }

 private:
  uint64_t period_ticks_;
  DdaEngine dda_;
  BackendTimingModel timing_;
  BackendResult r_;
  std::optional<TriangleSampler> sampler_;
  std::optional<ModelSeries> series_;  // report.html's, unless GIRTD_NO_SERIES
};

}  // namespace

std::unique_ptr<Backend> make_approx_backend(const Params& p, std::optional<double> sample_rate) {
  return std::make_unique<ApproxBackend>(p, sample_rate);
}

}  // namespace girtd
