// Runs a trace through one untimed back end, frame by frame (clear, draw,
// swap), optionally recording the stream at a stage boundary (--dump). The
// timed back ends run in the SystemC pipeline (pipeline/pipeline.hpp); both
// go through the same frame driver (backends/frame_driver.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "backends/backend.hpp"
#include "backends/backend_entry.hpp"
#include "backends/dump_tap.hpp"
#include "backends/prune_plan.hpp"
#include "common/input_error.hpp"
#include "timeline/wave_options.hpp"
#include "io/png_io.hpp"
#include "io/trace.hpp"

namespace girtd {

struct RenderOutput {
  RunStats stats;
  RgbImage shown;                   // the displayed buffer after the last frame
  std::vector<uint16_t> z;          // the Z buffer after the last frame
  std::vector<RgbImage> per_frame;  // with keep_all_frames
  std::vector<std::string> wave_files;  // the waveform and its .gtkw and pixel log
  // Bad input found only at the end of a run (a --wave window or scope that
  // recorded nothing): the caller reports it, nothing is written.
  std::optional<InputError> problem;
};

struct RenderOptions {
  bool keep_all_frames = false;
  std::optional<DumpRequest> dump;
  bool progress = false;  // a progress line on stderr for runs longer than a second
  // The polygon-level trace the rendered one came from (models, scenes), for
  // --dump polygons=FILE; frames correspond one to one.
  const Trace* polygon_source = nullptr;
  std::optional<WaveOptions> wave;  // --wave (the rtl back end)
  PrunePlan prune;                  // what the simulator may leave out (render --no-prune: nothing)
  std::optional<double> sample_timing;  // approx: time this fraction of the triangles (backends/sampled_timing.hpp)
};

// `backend`: an untimed entry (engine/backend_registry.hpp).
RenderOutput render_trace(const BackendEntry& backend, const Trace& trace, const Params& params,
                          const RenderOptions& opt);

// What a run asks of the back end it makes.
BackendRequest backend_request(const RenderOptions& opt);

}  // namespace girtd
