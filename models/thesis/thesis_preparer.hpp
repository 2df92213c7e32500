// prepdda of the thesis appendix (docs/design.md §11), in its own units and in
// single precision as the 1988 program computed: screen map, winding, edge
// equations (a zero-length edge gets D = 1), the start-point search, the
// limits one pixel wider than the triangle, and ftol (truncation toward zero)
// into the program's 32-bit registers. The OCR readings are listed in
// models/thesis/README.md.
#pragma once

#include <optional>

#include "common/types.hpp"
#include "config/params.hpp"
#include "dda/dda_params.hpp"

namespace girtd {

// A vertex in the program's units: x in -1..1, y in -0.75..0.75 pointing up,
// z in 0..1 (smaller nearer), r g b in 0..1, t the opacity in 0..1.
using ThesisVertex = Vertex;

// The parameter set DDApix starts from (registers in Params::thesis formats),
// or nullopt when prepdda returns 0 (no area, or no start point).
std::optional<DdaParams> thesis_prepare(const std::array<ThesisVertex, 3>& v, const Params& p);

// ftol: the program's float -> long that truncates toward zero.
int64_t thesis_ftol(float f);

}  // namespace girtd
