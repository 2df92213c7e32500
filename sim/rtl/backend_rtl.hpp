// The rtl back end: the Verilated girtd_backend (hw/backend: DDA -> FIFO ->
// HAD + cache -> VRAM) driven on its base tick from C++. Frames are cleared
// through the serial port, triangles fed to the DDA's parameter port, the
// cache flushed and the buffers swapped; the shown buffer and Z are read
// through a backdoor. One interface, Backend's with its ModeledTime
// (backends/backend.hpp), for the pipeline, regress, the benches and the tests; the SystemC stage
// around it synchronizes only when a parameter set changes hands
// (stepping Verilator's --cc model by hand measured 5-15x faster than its
// --sc model's pins on an sc_clock).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "backends/backend.hpp"

class VerilatedFstC;

namespace girtd {

// Keep one instance alive at a time: two live Verilated models of the same
// top (even in separate contexts) share scope names, and Verilator 5.006
// deadlocks destroying the second (seen in testbench/pipeline).
class BackendRtl : public Backend, public ModeledTime {
 public:
  using Backend::begin_frame;
  using Backend::draw;
  void begin(const FrameSource& input) override { require_pipeline_input(input); }
  ModeledTime* modeled_time() override { return this; }
  // A frame cleared to `background` (drivers without frame settings).
  void begin_frame(Rgb background) {
    FrameSettings s;
    s.background = background;
    begin_frame(s);
  }
  BackendRtl* rtl() override { return this; }

  // Called twice on every base tick (waveforms): with the clock low, before
  // the rising edge, and after it.
  struct TickProbe {
    uint64_t tick;     // the tick whose rising edge this is (ticks since reset)
    bool rising;       // false: clock low, before the edge; true: after it
    bool pixel_push;   // the DDA pushes a pixel into the FIFO at this edge
    int pixel_x, pixel_y;
  };
  virtual void on_tick(std::function<void(const TickProbe&)> hook) = 0;
  // Record report.html's heat maps (screen_maps()) from here on; the
  // pipeline asks when it records series, regress and the benches do not.
  virtual void record_screen_maps() = 0;
  // The traced build only: record every signal into an FST writer.
  virtual void trace(VerilatedFstC* tfp) = 0;
};

// `x_seed` != 0 randomizes X/uninitialized state (meaningful in the check
// build). `traced`: the build with FST tracing compiled in (for --wave).
std::unique_ptr<BackendRtl> make_backend_rtl(const Params& p, uint32_t x_seed = 0, bool traced = false);

}  // namespace girtd
