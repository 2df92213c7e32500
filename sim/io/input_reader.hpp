// Any input a render takes, by what it is: a trace (its header, or --level),
// a scene (.json) or a model (assimp's formats). Scenes and models come back
// as polygon-level traces. Throws InputError, `FILE:LINE: what`.
#pragma once

#include <optional>
#include <string>

#include "config/params.hpp"
#include "io/trace.hpp"

namespace girtd {

// `camera`: a model file's camera by name (render --camera); "" the default.
Trace read_input(const std::string& path, std::optional<TraceLevel> level, const Params& params,
                 const std::string& camera = "");

}  // namespace girtd
