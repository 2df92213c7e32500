// Runs an input through one untimed back end, frame by frame (clear, draw,
// swap), optionally recording the stream at a stage boundary (--dump). The
// timed back ends run in the SystemC pipeline (pipeline/pipeline.hpp); both
// go through the same frame driver (backends/frame_driver.hpp).
#pragma once

#include <functional>
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
#include "io/frame_source.hpp"

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

// Each frame's picture as its swap ends it, numbered from 0.
using FrameCallback = std::function<void(size_t frame, const RgbImage& picture)>;

struct RenderOptions {
  bool keep_all_frames = false;  // RenderOutput::per_frame (every frame held to the end)
  FrameCallback on_frame;        // each frame handed on as it ends (nothing held)
  std::optional<DumpRequest> dump;
  bool progress = false;  // a progress line on stderr for runs longer than a second
  std::optional<WaveOptions> wave;  // --wave (the rtl back end)
  PrunePlan prune;                  // what the simulator may leave out (render --no-prune: nothing)
  std::optional<double> sample_timing;  // approx: time this fraction of the triangles (backends/sampled_timing.hpp)
};

// `backend`: an untimed entry (engine/backend_registry.hpp). Polygon input
// goes through the front end here, a frame at a time (report's frontend).
RenderOutput render_frames(const BackendEntry& backend, FrameSource& input, const Params& params,
                           const RenderOptions& opt);

// What a run asks of the back end it makes.
BackendRequest backend_request(const RenderOptions& opt);

}  // namespace girtd
