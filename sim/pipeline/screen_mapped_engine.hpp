// The rtl engine with report.html's heat maps: the RTL draws, and the golden
// DDA (bit- and clock-exact with the RTL's, `girtd regress`) replays each
// parameter set to tell the screen-map recorder which pixels, in which
// order, and how many clocks: a few per cent of the RTL's own time.
#pragma once

#include <memory>

#include "backends/backend_engine.hpp"

namespace girtd {

std::unique_ptr<BackendEngine> with_screen_maps(std::unique_ptr<BackendEngine> inner, const Params& p);

}  // namespace girtd
