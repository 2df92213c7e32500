// Float geometry shared by the reference rasterizer and the DDA preparer, so
// both decide the same things the same way: winding, normalized edge
// equations (inside positive), attribute planes, the Q-widened pixel box and
// the start point of §3 (selection and window clip).
#pragma once

#include <array>
#include <optional>

#include "common/types.hpp"

namespace girtd {

// D(x, y) = a x + b y + c, |(a, b)| = 1, positive inside.
struct EdgeEquation {
  double a = 0, b = 0, c = 0;
  double at(double x, double y) const { return a * x + b * y + c; }
};

// One interpolated attribute: P(x, y) = p0 + (x - x0) dx + (y - y0) dy.
struct AttributePlane {
  double x0 = 0, y0 = 0, p0 = 0, dx = 0, dy = 0;
  double at(double x, double y) const { return p0 + (x - x0) * dx + (y - y0) * dy; }
};

enum Attr { kR = 0, kG, kB, kT, kZ, kAttrCount };

struct TriangleSetup {
  std::array<Vertex, 3> v;           // counter-clockwise on the y-down screen
  std::array<EdgeEquation, 3> edge;  // edge i runs from v[i] to v[(i+1)%3]
  std::array<bool, 3> interior{};    // edge i is an interior edge (Triangle::interior_edges)
  bool reordered = false;            // given clockwise on screen (the other face of its surface)
  std::array<AttributePlane, kAttrCount> attr;
  double min_x, max_x, min_y, max_y;
};

// nullopt when the triangle has no area (pv = 0), the thesis' rule.
std::optional<TriangleSetup> setup_triangle(const Triangle& t);

// The layer a triangle's pixels belong to when counting seams (Had's
// `reblended`): its surface's faces that point the same way on screen
// (a transparent sphere's back faces and front faces are two layers). -1:
// the surface is not known.
inline int seam_layer(const Triangle& t, const TriangleSetup& s) {
  return t.surface < 0 ? -1 : 2 * t.surface + s.reordered;
}

struct PixelBox {
  int x0, y0, x1, y1;
  bool empty() const { return x0 > x1 || y0 > y1; }
};

// Lattice points within Q of the triangle's bounding box, cut to the window:
// the Xmin/Xmax/Ymax limits of §4 (and the start row's lower bound).
PixelBox fringe_box(const TriangleSetup& s, double q, const Window& w);

struct StartPoint {
  double x, y;
};

// §3 selection and window clip: the window's top-left corner if it is inside
// the triangle; else, of the vertices inside the window and the crossings of
// edges with the window border, the one with the smallest y (ties: smallest
// x). nullopt: the triangle misses the window and is discarded.
std::optional<StartPoint> select_start_point(const TriangleSetup& s, const Window& w);

// One edge as every triangle that shares it sees it (preparer.fill_rule
// top_left): measured from its end P that comes first by (y, x), along the
// normal of the direction away from P, so two neighbours' distances are exact
// negatives of each other and a tie (distance 0) goes to exactly one side.
struct SharedEdge {
  Vertex p;
  double nx = 0, ny = 0, len = 1;  // normal of the direction P -> other end, unnormalized, and its length
  double a = 0, b = 0;             // the unit normal
  int sign = 1;                    // +1: this triangle's inside is the positive side
  int ref_x = 0, ref_y = 0;        // the lattice point nearest the window's middle projected onto the edge's line
  // Normalized after the products, so a lattice point on an edge between
  // lattice points is exactly 0 (the tie the rule decides).
  double at(double x, double y) const { return sign * (nx * (x - p.x) + ny * (y - p.y)) / len; }
  // Top-left: the side whose inside lies right of the edge, or below a
  // horizontal one, keeps the pixels exactly on it.
  bool owns_ties() const { return sign * a > 0 || (sign * a == 0 && sign * b > 0); }
};

SharedEdge shared_edge(const TriangleSetup& s, int i, const Window& w);

// Norm_Q of §4: 1 for d >= 0, 1 + d/Q for -Q < d < 0, 0 for d <= -Q; Q = 0 a step.
double norm_q(double d, double q);

// Q must be 0 or 2^k, k = -4..3, for the hardware back ends (Norm is a shift).
bool is_hardware_q(double q);
int q_log2(double q);  // k for Q = 2^k (Q > 0)

}  // namespace girtd
