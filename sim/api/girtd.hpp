// The simulator as a library: load an input or take a scene document, merge
// configurations, render on one back end, get the report, the frame, the Z
// plane and the series. `girtd render` and the Python module (python/) are
// clients of this header; docs/python.md "C++" says how to link it.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "backends/run_stats.hpp"
#include "common/input_error.hpp"
#include "io/png_io.hpp"

namespace girtd {

// One --config layer: a file, or JSON merged the same way (errors name `origin`).
struct ConfigLayer {
  std::string file;
  nlohmann::json patch;  // used when `file` is empty
  std::string origin = "config";
};

struct RenderRequest {
  // A trace, a scene (.json) or a model file; with `scene`, the name the
  // scene's errors carry ("FILE:LINE: what" with LINE 0).
  std::string input;
  // A scene document (traces/FORMAT.md "Scene files") instead of a file;
  // relative model paths start at the working directory.
  std::optional<nlohmann::json> scene;
  std::string backend = "golden";  // a registry name (backend_list())
  std::vector<ConfigLayer> config;  // merged over the built-in one in order
  std::string level;                 // a trace without a header: its level
  std::string camera;                // a model file's camera by name ("": the file's first, else auto)
  int repeat = 1;                    // a one-frame input drawn N times
  bool keep_all_frames = false;      // RenderResult::per_frame (every frame held to the end)
  // Each frame's picture as its swap ends it, numbered from 0, nothing held
  // (what `girtd render --frames all` writes as the run goes).
  std::function<void(size_t frame, const RgbImage& picture)> on_frame;
  bool prune = true;                 // leave out what cannot change the picture
  std::optional<double> aa;          // dda.q_override
  std::optional<double> sample_timing;
  std::string dump;                  // LEVEL=FILE: the stream at a stage boundary
  std::string wave, wave_window;     // the rtl back end's waveform and its window
  std::vector<std::string> wave_scopes;
  bool progress = false;             // a progress line on stderr for long runs
  bool print_warnings = true;        // each warning on stderr as "warning: ..." when found
};

struct RenderResult {
  nlohmann::json report;              // report.json's keys and values
  RgbImage frame;                     // the shown buffer after the last frame
  std::vector<uint16_t> z;            // its Z plane, row-major
  std::vector<RgbImage> per_frame;    // with keep_all_frames
  std::vector<std::string> wave_files;  // the waveform, its .gtkw and the pixel log
  RunStats stats;                     // what the report was made from (the HTML page's series)
  // Bad input found at the end of a timed run (a waveform that recorded
  // nothing): returned, not thrown, since sanitizers cannot follow an
  // exception past SystemC's coroutine stacks (WaveFiles). The rest is empty.
  std::optional<InputError> problem;
};

// Renders in this process. Throws InputError ("FILE:LINE: what") for bad
// input, options the back end refuses, or a configuration it cannot build.
// A back end that elaborates SystemC (runs_once_per_process) can render
// once per process: use render_in_child_process for more.
RenderResult render(const RenderRequest& request);

// The same render in a forked child process, its result sent back through a
// pipe (RenderResult::stats stays empty). InputError, and a problem, cross
// as InputError.
RenderResult render_in_child_process(const RenderRequest& request);

// True when `backend` elaborates the SystemC pipeline, which a process can do once.
bool runs_once_per_process(const std::string& backend);

// The back ends as the registry lists them: name, summary, capabilities, refusals.
nlohmann::json backend_list();

// The merged configuration of `layers` (checked as a render would).
nlohmann::json merged_config(const std::vector<ConfigLayer>& layers);

// The RTL build key `layers` need, and whether this library holds that
// elaboration (else `girtd render` builds an RTL variant and runs in it).
std::string needed_rtl_key(const std::vector<ConfigLayer>& layers);
bool holds_rtl_key(const std::string& key);

}  // namespace girtd
