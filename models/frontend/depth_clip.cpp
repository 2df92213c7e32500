#include "frontend/depth_clip.hpp"

namespace girtd {

CameraVertex depth_crossing(const CameraVertex& p1, const CameraVertex& p2, double c) {
  const double w1 = c - p2.s.z, w2 = p1.s.z - c, sum = p1.s.z - p2.s.z;
  auto mix = [&](double a, double b) { return (a * w1 + b * w2) / sum; };
  CameraVertex v;
  v.s = {mix(p1.s.x, p2.s.x), mix(p1.s.y, p2.s.y), c};  // exactly on the plane
  v.r = mix(p1.r, p2.r);
  v.g = mix(p1.g, p2.g);
  v.b = mix(p1.b, p2.b);
  v.t = mix(p1.t, p2.t);
  v.created = true;
  return v;
}

std::vector<CameraVertex> depth_clip(const std::vector<CameraVertex>& poly, double c) {
  std::vector<CameraVertex> out;
  depth_clip(poly, c, out);
  return out;
}

void depth_clip(const std::vector<CameraVertex>& poly, double c, std::vector<CameraVertex>& out) {
  out.clear();
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const CameraVertex& a = poly[i];
    const CameraVertex& b = poly[(i + 1) % n];
    const bool a_in = a.s.z > c, b_in = b.s.z > c;
    if (a_in) out.push_back(a);
    if (a_in && !b_in) out.push_back(depth_crossing(a, b, c));
    if (!a_in && b_in) out.push_back(depth_crossing(b, a, c));
  }
}

}  // namespace girtd
