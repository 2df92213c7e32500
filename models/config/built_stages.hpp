// Which front-end stages a configuration builds: what the cost model charges
// boards for and what the timed pipeline gives time to.
#pragma once

#include <string>

#include "config/params.hpp"

namespace girtd {

// The culling stage is this project's addition, built only when the config
// turns culling on (`culling.objects`, or `culling.back_faces` always).
// Without it, the back-face test an input asks for runs on the lighting
// board, which already forms dot products of normals with the view direction
// (|cos t| for transparency, thesis §4.3.8).
bool culling_stage_built(const Params& p);

// Whether a stage of `pipeline.flops_per_s` is in the design.
bool stage_built(const Params& p, const std::string& stage);

}  // namespace girtd
