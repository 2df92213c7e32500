// The Verilated back end (hw/backend: DDA -> FIFO -> HAD + cache -> VRAM)
// driven on its base tick from C++: frames are cleared through the serial
// port, triangles fed to the DDA's parameter port, the cache flushed and the
// buffers swapped; the shown buffer and Z are read through a backdoor.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "common/types.hpp"
#include "config/params.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_params.hpp"

class VerilatedFstC;

namespace girtd {

struct BackendCounters {
  uint64_t ticks = 0;              // base ticks since reset
  uint64_t dda_clocks = 0;         // DDA clocks on triangles
  uint64_t dda_wait_ticks = 0;     // DDA waiting on a full FIFO
  uint64_t pixels_generated = 0;   // pixels the DDA pushed into the FIFO
  uint64_t written = 0, blended = 0, z_rejected = 0, dropped = 0;
  uint64_t page_misses = 0;
  uint64_t had_busy_ticks = 0, had_vram_wait_ticks = 0;
  int fifo_max = 0;
  std::array<uint64_t, static_cast<size_t>(DdaState::kCount)> dda_state_clocks{};  // DDA clocks per state (models/dda numbering)
  uint64_t accounted() const { return written + blended + z_rejected + dropped; }
};

// Keep one instance alive at a time: two live Verilated models of the same
// top (even in separate contexts) share scope names, and Verilator 5.006
// deadlocks destroying the second (seen in testbench/pipeline).
class BackendRtl {
 public:
  // `x_seed` != 0 randomizes X/uninitialized state (meaningful in the check
  // build). `traced`: the build with FST tracing compiled in (for --wave).
  explicit BackendRtl(const Params& p, uint32_t x_seed = 0, bool traced = false);
  ~BackendRtl();
  BackendRtl(const BackendRtl&) = delete;
  BackendRtl& operator=(const BackendRtl&) = delete;

  void begin_frame(Rgb background);  // clear the back buffer and Z (serial port)
  void draw(const DdaParams& d);     // hand one parameter set to the DDA
  void end_frame();                  // drain, write the cache page back, swap
  void drain();                      // clock until DDA, FIFO, HAD and VRAM are idle
  // For a simulation that hands over parameter sets as they arrive
  // (sim/pipeline): clock until the DDA could take one on this tick, and
  // clock with no input up to a given tick.
  void step_until_ready();
  void step_to(uint64_t tick);
  uint64_t ticks() const;
  // Called twice on every base tick (waveforms): with the clock low, before
  // the rising edge, and after it.
  struct TickProbe {
    uint64_t tick;     // the tick whose rising edge this is (ticks since reset)
    bool rising;       // false: clock low, before the edge; true: after it
    bool pixel_push;   // the DDA pushes a pixel into the FIFO at this edge
    int pixel_x, pixel_y;
  };
  void on_tick(std::function<void(const TickProbe&)> hook);
  // The traced build only: record every signal into an FST writer.
  void trace(VerilatedFstC* tfp);

  BackendCounters counters() const;
  // The shown buffer (1024 x 1024 x 3 bytes) and Z, through the backdoor.
  std::vector<uint8_t> shown_rgb() const;
  std::vector<uint16_t> z_plane() const;

 private:
  std::unique_ptr<class BackendRtlDriver> impl_;
};

}  // namespace girtd
