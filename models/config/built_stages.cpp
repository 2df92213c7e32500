#include "config/built_stages.hpp"

namespace girtd {

bool culling_stage_built(const Params& p) { return p.cull_objects || p.cull_back_faces_always; }

bool stage_built(const Params& p, const std::string& stage) { return stage != "culling" || culling_stage_built(p); }

}  // namespace girtd
