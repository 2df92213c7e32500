// The rtl back end: the Verilated girtd_backend (DDA, FIFO, HAD, cache,
// VRAM), clocked tick by tick in C++; the SystemC stage around it only
// synchronizes when a parameter set changes hands (TOOLCHAIN.md: stepping
// the --cc model by hand is 5-15x faster than --sc pins on an sc_clock).
#include "pipeline/back_end_engine.hpp"
#include "rtl/backend_rtl.hpp"

namespace girtd {
namespace {

class RtlEngine : public BackEndEngine {
 public:
  RtlEngine(const Params& p, bool traced) : rtl_(p, 0, traced), width_(p.screen_width), height_(p.screen_height) {}
  uint64_t ready_tick() override {
    rtl_.step_until_ready();
    return rtl_.ticks();
  }
  void idle_until(uint64_t tick) override { rtl_.step_to(tick); }
  void begin_frame(const FrameSettings& s) override { rtl_.begin_frame(s.background); }
  void draw(const DdaParams& d) override {
    rtl_.draw(d);
    ++triangles_;
  }
  void drain() override { rtl_.drain(); }
  void end_frame() override { rtl_.end_frame(); }
  uint64_t now_tick() const override { return rtl_.ticks(); }
  BackEndResult result() const override {
    const BackendCounters c = rtl_.counters();
    BackEndResult r;
    r.ticks = c.ticks;
    r.triangles_drawn = triangles_;
    r.pixels_generated = c.pixels_generated;
    r.had = HadCounts{c.written, c.blended, c.z_rejected, c.dropped};
    r.dda.cycles = c.dda_clocks;
    r.dda.emitted = c.pixels_generated;
    for (size_t i = 0; i < r.dda.per_state.size(); ++i) r.dda.per_state[i] = c.dda_state_clocks[i];
    r.dda_wait_ticks = c.dda_wait_ticks;
    r.page_misses = c.page_misses;
    r.had_busy_ticks = c.had_busy_ticks;
    r.had_vram_wait_ticks = c.had_vram_wait_ticks;
    r.fifo_max = static_cast<uint64_t>(c.fifo_max);
    return r;
  }
  RgbImage shown() const override {
    RgbImage img;
    img.width = width_;
    img.height = height_;
    img.rgb = rtl_.shown_rgb();
    return img;
  }
  std::vector<uint16_t> z_plane() const override { return rtl_.z_plane(); }
  BackendRtl* rtl() override { return &rtl_; }

 private:
  BackendRtl rtl_;
  int width_, height_;
  uint64_t triangles_ = 0;
};

}  // namespace

std::unique_ptr<BackEndEngine> make_rtl_engine(const Params& p, bool traced) {
  return std::make_unique<RtlEngine>(p, traced);
}

}  // namespace girtd
