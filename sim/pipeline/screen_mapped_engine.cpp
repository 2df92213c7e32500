#include "pipeline/screen_mapped_engine.hpp"

#include "backends/screen_maps.hpp"
#include "dda/dda_engine.hpp"

namespace girtd {
namespace {

class ScreenMappedEngine : public BackendEngine {
 public:
  ScreenMappedEngine(std::unique_ptr<BackendEngine> inner, const Params& p)
      : inner_(std::move(inner)), dda_(p), maps_(p) {}
  uint64_t ready_tick() override { return inner_->ready_tick(); }
  void idle_until(uint64_t tick) override { inner_->idle_until(tick); }
  void begin_frame(const FrameSettings& s) override {
    inner_->begin_frame(s);
    maps_.begin_frame();
  }
  void draw(const DdaParams& d) override {
    inner_->draw(d);
    const DdaRunStats st = dda_.run(d, [&](const DdaEmit& e) { maps_.pixel(e.pixel.x, e.pixel.y); });
    maps_.end_triangle(st.cycles, st.emitted);
  }
  void drain() override { inner_->drain(); }
  void end_frame() override { inner_->end_frame(); }
  uint64_t now_tick() const override { return inner_->now_tick(); }
  BackendResult result() const override { return inner_->result(); }
  BackendCounters counters() const override { return inner_->counters(); }
  RgbImage shown() const override { return inner_->shown(); }
  std::vector<uint16_t> z_plane() const override { return inner_->z_plane(); }
  void prune(const PrunePlan& plan) override {
    inner_->prune(plan);
    dda_.skip_unreachable_wraps(plan.unreachable_wraps);
  }
  std::optional<ScreenMaps> screen_maps() const override { return maps_.maps(); }
  std::optional<FifoSeries> fifo_levels(uint64_t end) const override { return inner_->fifo_levels(end); }
  BackendRtl* rtl() override { return inner_->rtl(); }

 private:
  std::unique_ptr<BackendEngine> inner_;
  DdaEngine dda_;
  ScreenMapRecorder maps_;
};

}  // namespace

std::unique_ptr<BackendEngine> with_screen_maps(std::unique_ptr<BackendEngine> inner, const Params& p) {
  return std::make_unique<ScreenMappedEngine>(std::move(inner), p);
}

}  // namespace girtd
