// The back end as the pipeline's last SystemC module. A timed back end keeps its
// own clock in base ticks and may run ahead of SystemC time; the two are
// brought level whenever a token changes hands, so the preparer sees the
// FIFO slot freed at the tick the DDA takes the parameter set, and a DDA
// waiting for input waits in SystemC time.
#pragma once

#include <systemc>

#include <chrono>
#include <functional>
#include <vector>

#include "dda/dda_params.hpp"
#include "backends/backend.hpp"
#include "pipeline/counter_timeline.hpp"
#include "timeline/stage_activity.hpp"
#include "pipeline/token.hpp"
#include "rtl/backend_rtl.hpp"
#include "timeline/series_switch.hpp"
#include "wave/wave_recorder.hpp"

namespace girtd {

class BackendStage : public sc_core::sc_module {
 public:
  sc_core::sc_fifo_in<Token<DdaParams>> in;

  // Called after each frame's swap (for --frames all) and, when the run is
  // long, with progress (frame index, triangles so far).
  using FrameDone = std::function<void(size_t frame)>;
  using Progress = std::function<void(size_t frame, uint64_t triangles, double modeled_s)>;

  SC_HAS_PROCESS(BackendStage);
  BackendStage(const sc_core::sc_module_name& name, Backend& backend, const std::vector<FrameSettings>& frames,
               double tick_ns, double dda_clock_ns, StageActivity& activity, FifoActivity& in_fifo,
               FrameDone frame_done, Progress progress);

  bool finished() const { return finished_; }
  // Record a waveform: every tick in the window is dumped once SystemC
  // time has reached it (rtl: the RTL and the SystemC side; approx: the
  // SystemC side alone).
  void record(WaveRecorder* rec) { wave_ = rec; }
  // Bring SystemC time level with the RTL at every tick (pipeline.rtl_sync).
  void sync_every_tick(bool on) { lockstep_ = on; }
  uint64_t end_tick() const { return end_tick_; }  // the last frame's swap
  // Ticks spent clearing frames and, at their ends, writing the cache back
  // and swapping (not drawing).
  uint64_t frame_ticks() const { return frame_ticks_; }
  // Per frame: the tick its swap ended, and the pixels generated up to then.
  const std::vector<uint64_t>& frame_end_ticks() const { return frame_end_ticks_; }
  const std::vector<uint64_t>& frame_end_pixels() const { return frame_end_pixels_; }
  // The DDA's and the HAD's busy / starved / blocked over modeled time.
  const CounterTimeline& timeline() const { return timeline_; }

 private:
  void run();
  sc_core::sc_time at(uint64_t tick) const;
  uint64_t tick_of(const sc_core::sc_time& t) const;  // the first tick at or after t
  void sync_to(uint64_t tick);
  void sync_to_ns(double t_ns);
  Token<DdaParams> next_token();
  void on_tick(const BackendRtl::TickProbe& p);
  void sample();

  Backend& backend_;
  ModeledTime& time_;  // backend_'s
  const std::vector<FrameSettings>& frames_;
  double tick_ns_;
  StageActivity& a_;
  FifoActivity& in_fifo_;
  FrameDone frame_done_;
  Progress progress_;
  WaveRecorder* wave_ = nullptr;
  bool lockstep_ = false;
  size_t frame_ = 0;
  bool finished_ = false;
  uint64_t end_tick_ = 0;
  uint64_t frame_ticks_ = 0;
  std::vector<uint64_t> frame_end_ticks_, frame_end_pixels_;
  CounterTimeline timeline_;
  bool series_ = record_series();
};

}  // namespace girtd
