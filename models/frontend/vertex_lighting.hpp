// §3 lighting, second half: the colour and opacity of one vertex.
//   colour = R Id + R If max(0, I.N) + 255 CRE(i) max(0, (2(N.I)N - I).E)^n If
// summed over the directional lights, saturated to 0..255; i = acos(N.I) is
// the angle of incidence, CRE interpolated linearly between its 15-degree
// samples; no specular from a light behind the surface (N.I <= 0).
// Opacity T = 1 - Tf, Tf = Tmin + (Tmax - Tmin)|N.E|.
#pragma once

#include "frontend/world_frame.hpp"

namespace girtd {

struct LitVertex {
  double r = 0, g = 0, b = 0;  // 0..255
  double t = 1;                // opacity 0..1 (the DDA's T)
};

// CRE at `incidence_deg` (clamped to 0..90), linear between samples.
double cre_at(const Surface& s, double incidence_deg);

// `n`: unit vertex normal; `e`: unit vector from the vertex toward the camera centre.
LitVertex light_vertex(const Surface& s, const LightSet& lights, Vec3 n, Vec3 e);

}  // namespace girtd
