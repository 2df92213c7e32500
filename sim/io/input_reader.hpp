// Any input a render takes, by what it is: a trace (its header, or --level),
// a scene (.json) or a model (assimp's formats). Scenes and models come back
// as polygon-level input, a scene's frames placed as the run takes them.
// Throws InputError, `FILE:LINE: what`.
#pragma once

#include <optional>
#include <string>

#include "config/params.hpp"
#include "io/frame_source.hpp"

namespace girtd {

// `camera`: a model file's camera by name (render --camera); "" the default.
FrameSource open_input(const std::string& path, std::optional<TraceLevel> level, const Params& params,
                       const std::string& camera = "");

}  // namespace girtd
