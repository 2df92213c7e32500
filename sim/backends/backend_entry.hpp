// What one back end is, as properties: the registry (engine/backend_registry.hpp)
// holds one entry per back end, and code below it is handed an entry rather
// than a name. What differs between back ends is a capability here, never a
// comparison with a name.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "backends/backend.hpp"
#include "config/params.hpp"

namespace girtd {

enum Capability : unsigned {
  kDrawsWithDda = 1u << 0,   // runs the hardware's preparer and DDA: counts DDA clocks; Q is a shift
  kModelsTime = 1u << 1,     // the SystemC pipeline: modeled time, stage activity, waveforms
  kSeesSurfaces = 1u << 2,   // its HAD knows the triangles' surfaces (seams are counted)
  kSamplesTiming = 1u << 3,  // --sample-timing: times a sample of the triangles
  kRunsRtl = 1u << 4,        // the Verilated RTL: an RTL build key, RTL signals in waveforms
  kExactPicture = 1u << 5,   // double precision: the yardstick pictures are judged against
  kExactTiming = 1u << 6,    // tick by tick in the RTL: the yardstick modeled time is judged against
};

// An option a back end cannot honour: refused before the input is read.
struct BackendRefusal {
  std::string option;  // as the CLI spells it, e.g. "--wave"
  std::string reason;  // the rest of the one-line error
};

// How a back end is made for one run.
struct BackendRequest {
  bool traced = false;                // the RTL built with FST tracing (--wave)
  std::optional<double> sample_rate;  // --sample-timing
};

struct BackendEntry {
  std::string name;     // --backend NAME
  std::string summary;  // one line for --help and the docs
  unsigned capabilities = 0;
  std::vector<BackendRefusal> refuses;
  // Untimed back ends are driven frame by frame by the render session
  // (backends/render_session.hpp); timed ones are the SystemC pipeline's
  // back-end stage (pipeline/pipeline.hpp).
  std::function<std::unique_ptr<Backend>(const Params&, const BackendRequest&)> make;

  bool has(Capability c) const { return (capabilities & c) != 0; }
  bool timed() const { return has(kModelsTime); }
  bool has_dda() const { return has(kDrawsWithDda); }
  // The refusal of `option`, if this back end refuses it.
  const BackendRefusal* refusal(const std::string& option) const {
    for (const BackendRefusal& r : refuses)
      if (r.option == option) return &r;
    return nullptr;
  }
};

}  // namespace girtd
