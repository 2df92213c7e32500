#include "claims/equilateral.hpp"

#include <cmath>

namespace girtd {

Triangle equilateral_200(double cx, double cy, double angle, double z) {
  const double s = std::sqrt(800.0 / std::sqrt(3.0));
  const double circumradius = s / std::sqrt(3.0);  // 2h/3
  Triangle t;
  const double colours[3][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
  for (int i = 0; i < 3; ++i) {
    // Apex (i = 0) straight up at angle 0; y grows downward.
    const double a = angle + i * 2.0 * M_PI / 3.0;
    Vertex& v = t.v[i];
    v.x = cx + circumradius * std::sin(a);
    v.y = cy - circumradius * std::cos(a);
    v.z = z;
    v.r = colours[i][0];
    v.g = colours[i][1];
    v.b = colours[i][2];
    v.t = 1.0;
  }
  return t;
}

void for_each_subpixel_position(double x0, double y0, const std::function<void(double, double)>& fn) {
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) fn(x0 + (i + 0.5) / 8, y0 + (j + 0.5) / 8);
}

double thesis_wasted_states(const Triangle& t) {
  // Centroid tells which side of each edge is outward.
  const double gx = (t.v[0].x + t.v[1].x + t.v[2].x) / 3.0;
  const double gy = (t.v[0].y + t.v[1].y + t.v[2].y) / 3.0;
  double wasted = 0;
  for (int i = 0; i < 3; ++i) {
    const Vertex& p = t.v[i];
    const Vertex& q = t.v[(i + 1) % 3];
    const double dx = std::fabs(q.x - p.x), dy = std::fabs(q.y - p.y);
    const double nx = q.y - p.y, ny = -(q.x - p.x);
    const bool inward = nx * (gx - p.x) + ny * (gy - p.y) > 0;
    const double outward_ny = inward ? -ny : ny;
    if (outward_ny < 0) wasted += 2 * dy;  // outward normal points up (y grows down)
    else wasted += dx + 1.5 * dy;
  }
  return wasted;
}

}  // namespace girtd
