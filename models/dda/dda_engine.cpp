#include "dda/dda_engine.hpp"

#include "dda/dda_state_machine.hpp"

namespace girtd {

DdaRunStats DdaEngine::run(const DdaParams& in, const PixelSink& sink, const ClockProbe& probe) const {
  return run_any(in, sink, probe);
}

}  // namespace girtd
