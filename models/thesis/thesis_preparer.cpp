#include "thesis/thesis_preparer.hpp"

#include <algorithm>
#include <cmath>

#include "common/fixed_point.hpp"

namespace girtd {
namespace {

struct Edge {
  float dx, dy, d;  // D = dx x + dy y + d
};

// One edge as prepdda computes it; `flip` is the program's q.
Edge edge(float ax, float ay, float bx, float by, bool flip) {
  const float dx = ay - by, dy = bx - ax;
  float di = std::sqrt(dx * dx + dy * dy);
  if (di == 0) return {0, 0, 1.0f};  // degenerate edge: D = 1, never outside
  di = 1 / di;
  Edge e{di * dx, di * dy, 0};
  e.d = -e.dx * ax - e.dy * ay;
  if (flip) e = {-e.dx, -e.dy, -e.d};
  return e;
}

}  // namespace

int64_t thesis_ftol(float f) { return f < 0 ? -static_cast<int64_t>(-f) : static_cast<int64_t>(f); }

std::optional<DdaParams> thesis_prepare(const std::array<ThesisVertex, 3>& v, const Params& p) {
  const float kc = static_cast<float>(p.thesis.kc);
  const float xmax_screen = float(p.thesis.width - 1), ymax_screen = float(p.thesis.height - 1);
  float px[3], py[3];
  for (int i = 0; i < 3; ++i) {
    px[i] = kc * (1.0f + float(v[i].x));
    py[i] = kc * (0.75f - float(v[i].y));
  }
  float pv = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
  if (pv == 0) return std::nullopt;
  const bool q = pv < 0;  // reading of "q=(pv)>0?-1;": flip so the interior is positive
  pv = 1 / pv;
  const Edge e[3] = {edge(px[0], py[0], px[1], py[1], q), edge(px[1], py[1], px[2], py[2], q),
                     edge(px[2], py[2], px[0], py[0], q)};
  auto inside_at = [&](float x, float y) {
    return (e[0].dx * x + e[0].dy * y + e[0].d) >= 0 && (e[1].dx * x + e[1].dy * y + e[1].d) >= 0 &&
           (e[2].dx * x + e[2].dy * y + e[2].d) >= 0;
  };

  // Start point: the vertex of smallest y, if inside the screen ...
  float xs = px[0], ys = py[0];
  for (int i = 1; i < 3; ++i)
    if (py[i] < ys) {
      ys = py[i];
      xs = px[i];
    }
  if (ys > ymax_screen) return std::nullopt;
  bool found = xs >= 0 && xs <= xmax_screen && ys >= 0;
  // ... else a top corner of the screen inside the triangle ...
  if (!found) {
    ys = 0;
    xs = 0;
    found = inside_at(0, 0);
    if (!found) {
      xs = xmax_screen;
      found = inside_at(xs, 0);
    }
  }
  // ... else where an edge crosses the top border ...
  if (!found) {
    ys = 0;
    for (int i = 0; i < 3 && !found; ++i) {
      if (e[i].dx == 0) continue;
      xs = -e[i].d / e[i].dx;
      const Edge& a = e[(i + 1) % 3];
      const Edge& b = e[(i + 2) % 3];
      found = (a.dx * xs + a.d) >= 0 && (b.dx * xs + b.d) >= 0 && xs > 0 && xs < xmax_screen + 1;
    }
  }
  // ... else the highest crossing of the left, then the right border.
  if (!found) {
    ys = ymax_screen + 1;
    for (float bx : {0.0f, xmax_screen}) {
      for (int i = 0; i < 3; ++i) {
        if (e[i].dy == 0) continue;
        const float y = -(e[i].d + e[i].dx * bx) / e[i].dy;
        const Edge& a = e[(i + 1) % 3];
        const Edge& b = e[(i + 2) % 3];
        if ((a.dx * bx + a.dy * y + a.d) >= 0 && (b.dx * bx + b.dy * y + b.d) >= 0 && y > 0 && y < ymax_screen &&
            ys > y) {
          ys = y;
          xs = bx;
        }
      }
    }
    if (ys > ymax_screen) return std::nullopt;
    ys -= 1;  // reading of "ys--1;": one row up, so the Y++ of lb2 lands on the crossing row
  }

  DdaParams d;
  const float e16 = 65536.0f, e24 = 16777216.0f, e32 = 4.2949e9f;
  for (int i = 0; i < 3; ++i) {
    d.ep[kEpD1 + i] = {thesis_ftol(e16 * (e[i].d + e[i].dx * xs + e[i].dy * ys)), thesis_ftol(e16 * e[i].dx),
                       thesis_ftol(e16 * e[i].dy)};
  }
  const float x21 = pv * (px[1] - px[0]), y21 = pv * (py[1] - py[0]);
  const float x31 = pv * (px[2] - px[0]), y31 = pv * (py[2] - py[0]);
  const float xs1 = xs - px[0], ys1 = ys - py[0];
  auto plane = [&](float a1, float a2, float a3, float scale, EpInit& out) {
    const float dx = (a2 - a1) * y31 - (a3 - a1) * y21;
    const float dy = (a3 - a1) * x21 - (a2 - a1) * x31;
    const float at = a1 + dx * xs1 + dy * ys1;
    out = {thesis_ftol(scale * at), thesis_ftol(scale * dx), thesis_ftol(scale * dy)};
  };
  plane(float(v[0].r), float(v[1].r), float(v[2].r), e24, d.ep[kEpR]);
  plane(float(v[0].g), float(v[1].g), float(v[2].g), e24, d.ep[kEpG]);
  plane(float(v[0].b), float(v[1].b), float(v[2].b), e24, d.ep[kEpB]);
  plane(float(v[0].t), float(v[1].t), float(v[2].t), e16, d.ep[kEpT]);
  // Z is 0.32: the program's signed long would overflow for z >= 0.5; the
  // register is read as unsigned 32 bits (what the assembly's Z+2 word does).
  {
    const float dx = (float(v[1].z) - float(v[0].z)) * y31 - (float(v[2].z) - float(v[0].z)) * y21;
    const float dy = (float(v[2].z) - float(v[0].z)) * x21 - (float(v[1].z) - float(v[0].z)) * x31;
    const float at = float(v[0].z) + dx * xs1 + dy * ys1;
    auto to_u32 = [](float f) { return wrap_to_bits(thesis_ftol(f), 32); };
    d.ep[kEpZ] = {to_u32(e32 * at), thesis_ftol(e32 * dx), thesis_ftol(e32 * dy)};
  }
  d.x0 = static_cast<int>(xs);
  d.y0 = static_cast<int>(ys);
  float mx = std::max(std::max(px[0], px[1]), px[2]) + 1, mn = std::min(std::min(px[0], px[1]), px[2]) - 1;
  d.xmax = static_cast<int>(std::min(mx, xmax_screen));
  d.xmin = static_cast<int>(std::max(mn, 0.0f));
  d.ymax = static_cast<int>(std::min(std::max(std::max(py[0], py[1]), py[2]) + 1, ymax_screen));
  d.q = 1;  // PIX_INTERNO's D >= -1
  return d;
}

}  // namespace girtd
