// One FST timeline of a run: the Verilated back end's signals and the
// SystemC side (per stage: busy, starved, blocked, the occupancy of the
// FIFO in front of it, items in and out; the frame), in nanoseconds. The
// SystemC values are written through Verilator's own FST writer (trace
// callbacks), so both sides share one file and one time axis: the
// pipeline dumps at a tick only once SystemC time has reached it.
// Also writes FILE.gtkw (signals grouped by stage) and, with the RTL,
// FILE.pixels.csv (every pixel the DDA pushed in the window: the run's own
// log), all under temporary names until finish().
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "timeline/stage_activity.hpp"
#include "timeline/wave_options.hpp"

class VerilatedFstC;

namespace girtd {

class BackendRtl;
struct Params;

// Check --wave-scope names before a run (InputError naming the scopes
// there are). RTL paths: against the traced model's own hierarchy (one dump
// of a scratch instance, read back); call it before the run's back end
// exists (Verilator 5.006 wants one live instance of a model at a time).
// `pipeline...` paths: against the stages the run elaborated.
void check_rtl_wave_scopes(const std::vector<std::string>& scopes, const Params& p);
void check_pipeline_wave_scopes(const std::vector<std::string>& scopes, const std::vector<std::string>& stages);

// What finish() leaves: the files in place, or the input problem that kept
// them from it. Returned, not thrown: it comes after sc_start, and an
// exception there trips ASan, which cannot follow SystemC's coroutine
// stacks (Debian's libsystemc has no fiber annotations).
struct WaveFiles {
  std::vector<std::string> paths;  // the waveform, its .gtkw, the pixel log (rtl)
  std::optional<InputError> problem;
};

class WaveRecorder {
 public:
  explicit WaveRecorder(WaveOptions opt);
  ~WaveRecorder();  // without finish(): removes what it wrote
  WaveRecorder(const WaveRecorder&) = delete;
  WaveRecorder& operator=(const WaveRecorder&) = delete;

  // Before open(): what to record.
  void add_rtl(BackendRtl& rtl);
  void add_stage(const StageActivity& a, const FifoActivity* in_fifo);
  void open();

  bool wants(double t_ns) const { return t_ns >= opt_.t0_ns && t_ns <= opt_.t1_ns; }
  double window_end_ns() const { return opt_.t1_ns; }
  double window_start_ns() const { return opt_.t0_ns; }
  void set_frame(uint32_t frame) { frame_ = frame; }
  // Every recorded value as it is now, at t_ns (increasing).
  void dump(double t_ns);
  void log_pixel(double t_ns, int x, int y);

  // Closes the file, checks that the window and every --wave-scope
  // recorded something, writes the .gtkw and the .vcd if asked, and moves
  // every file into place.
  WaveFiles finish(double run_end_ns);

 private:
  struct StageProbe;
  struct TopProbe;
  WaveOptions opt_;
  std::string fst_tmp_, pixels_tmp_;
  std::unique_ptr<VerilatedFstC> tfp_;
  std::vector<std::unique_ptr<StageProbe>> stages_;
  std::unique_ptr<TopProbe> top_;
  std::vector<std::string> stage_names_;
  uint32_t frame_ = 0;
  bool has_rtl_ = false, finished_ = false;
  double last_dump_ns_ = -1;
  std::string pixel_log_;
};

}  // namespace girtd
