// The warning a run prints when a wrapped EP value was in use or the
// preparer clamped a value (report.json `numerics`): the picture is wrong
// in the triangles it names, and a wider EP avoids it.
#pragma once

#include <optional>
#include <string>

#include "backends/run_stats.hpp"
#include "config/params.hpp"

namespace girtd {

// "INPUT: wrapped EP values in use ...", or nothing when no triangle was affected.
std::optional<std::string> limit_warning(const std::string& input, const RunStats& s, const Params& p);
// "INPUT: N pixels blended twice by one surface ...", or nothing without seams.
std::optional<std::string> seam_warning(const std::string& input, const RunStats& s);
// Back faces of transparent surfaces a forced cull kept (culling.back_faces "always").
std::optional<std::string> culling_warning(const std::string& input, const RunStats& s);

}  // namespace girtd
