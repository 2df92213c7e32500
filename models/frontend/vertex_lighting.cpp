#include "frontend/vertex_lighting.hpp"

#include <algorithm>
#include <cmath>

namespace girtd {

double cre_at(const Surface& s, double incidence_deg) {
  const double a = std::clamp(incidence_deg, 0.0, 90.0) / kCreStepDeg;
  const int i = std::min(static_cast<int>(a), kCreSteps - 2);
  const double f = a - i;
  return s.cre[i] + (s.cre[i + 1] - s.cre[i]) * f;
}

LitVertex light_vertex(const Surface& s, const LightSet& lights, Vec3 n, Vec3 e) {
  double diffuse = lights.ambient;  // sum of the intensities multiplying R
  double specular = 0;              // sum of CRE (R.E)^n If, times 255 below
  for (const DirectionalLight& l : lights.directional) {
    const double ni = dot(n, l.toward);
    if (ni <= 0) continue;  // negative cosines clamp to 0: no diffuse, no highlight
    diffuse += l.intensity * ni;
    const Vec3 reflected = 2.0 * ni * n - l.toward;
    const double re = std::max(0.0, dot(reflected, e));
    const double incidence_deg = std::acos(std::min(1.0, ni)) * 180.0 / M_PI;
    specular += cre_at(s, incidence_deg) * std::pow(re, s.n) * l.intensity;
  }
  auto channel = [&](double reflectance) { return std::clamp(reflectance * diffuse + 255.0 * specular, 0.0, 255.0); };
  LitVertex out;
  out.r = channel(s.r);
  out.g = channel(s.g);
  out.b = channel(s.b);
  const double tf = s.t_min + (s.t_max - s.t_min) * std::fabs(dot(n, e));
  out.t = std::clamp(1.0 - tf, 0.0, 1.0);
  return out;
}

}  // namespace girtd
