#include "dda/dda_preparer.hpp"

#include <algorithm>
#include <cmath>

#include "common/fixed_point.hpp"
#include "common/triangle_setup.hpp"
#include "dda/steep_attributes.hpp"

namespace girtd {
namespace {

// Raw D values before they meet the register: exact integers, so the box
// test and the tie rule see what the DDA would add up.
constexpr double kRawLimit = 0x1p62;

int64_t raw_of(double x, int frac_bits) {
  return static_cast<int64_t>(std::clamp(std::round(x * pow2(frac_bits)), -kRawLimit, kRawLimit));
}

}  // namespace

DdaPreparer::EdgeRaw DdaPreparer::edge_raw(const EdgeEquation& e, int x0, int y0) const {
  const int f = params_.ep_d.frac_bits;
  return {raw_of(e.at(x0, y0), f), raw_of(e.a, f), raw_of(e.b, f)};
}

// From the shared reference point, in integers: both sides of the edge get
// exact negatives at every pixel.
DdaPreparer::EdgeRaw DdaPreparer::shared_edge_raw(const SharedEdge& e, int x0, int y0) const {
  const int f = params_.ep_d.frac_bits;
  const int64_t a = raw_of(e.a, f), b = raw_of(e.b, f);
  const int64_t at_ref = raw_of(e.a * (e.ref_x - e.p.x) + e.b * (e.ref_y - e.p.y), f);
  const int64_t v = at_ref + (int64_t{x0} - e.ref_x) * a + (int64_t{y0} - e.ref_y) * b;
  return {e.sign * v, e.sign * a, e.sign * b};
}

bool DdaPreparer::owns_ties(const EdgeRaw& d) { return d.dx > 0 || (d.dx == 0 && d.dy > 0); }

// Where the edge's line lies against the lattice points the DDA tests
// (the pixel box): D is linear, so its extremes are at two corners.
DdaPreparer::BoxSide DdaPreparer::edge_over_box(const EdgeRaw& d, int x0, int y0, const PixelBox& box,
                                                int64_t q_raw) {
  auto extreme = [&](bool high) {
    const int x = (d.dx > 0) == high ? box.x1 : box.x0;
    const int y = (d.dy > 0) == high ? box.y1 : box.y0;
    return static_cast<__int128>(d.v) + static_cast<__int128>(x - x0) * d.dx + static_cast<__int128>(y - y0) * d.dy;
  };
  if (extreme(false) >= 0) return BoxSide::kInside;
  if (extreme(true) <= -q_raw - (q_raw == 0)) return BoxSide::kOutside;  // Q = 0: every D < 0
  return BoxSide::kCrosses;
}

bool DdaPreparer::fit(int64_t raw, int64_t& reg) const {
  const FixFormat& f = params_.ep_d;
  reg = std::clamp(raw, f.raw_min(), f.raw_max());
  return reg == raw;
}

PrepareResult DdaPreparer::prepare(const Triangle& t, const FrameSettings& f, DdaParams& out) {
  const auto setup = setup_triangle(t);
  if (!setup) {
    ++counts_.degenerate;
    return PrepareResult::kDegenerate;
  }
  const TriangleSetup& s = *setup;
  const auto start = select_start_point(s, f.window);
  const PixelBox box = fringe_box(s, f.q, f.window);
  if (!start || box.empty()) {
    ++counts_.off_window;
    return PrepareResult::kOffWindow;
  }
  // Start row: the first lattice row at or below the start point's Q-fringe;
  // start column: the start point rounded, kept inside the limits.
  const int y0 = std::max(static_cast<int>(std::ceil(start->y - f.q)), box.y0);
  const int x0 = std::clamp(static_cast<int>(std::floor(start->x + 0.5)), box.x0, box.x1);
  if (y0 > box.y1) {
    ++counts_.no_lattice_row;
    return PrepareResult::kNoLatticeRow;
  }
  out = DdaParams{};
  out.x0 = x0;
  out.y0 = y0;
  out.xmin = box.x0;
  out.xmax = box.x1;
  out.ymax = box.y1;
  out.q = f.q;
  out.source_line = t.source_line;
  out.layer = seam_layer(t, s);

  auto convert = [&](double v, double dx, double dy, const FixFormat& fmt, EpInit& ep) {
    bool c1 = false, c2 = false, c3 = false;
    ep.v = to_fixed(v, fmt, &c1);
    ep.dx = to_fixed(dx, fmt, &c2);
    ep.dy = to_fixed(dy, fmt, &c3);
    counts_.clamps[size_t(&ep - &out.ep[0])] += c1 + c2 + c3;
    out.clamped = out.clamped || c1 || c2 || c3;
  };
  const int64_t q_raw = f.q == 0 ? 0 : to_fixed(f.q, params_.ep_d);
  for (int i = 0; i < 3; ++i) {
    const bool flagged = params_.edge_flags && s.interior[i];
    out.hard_edges |= static_cast<uint8_t>(flagged) << i;
    EdgeRaw d = params_.fill_top_left ? shared_edge_raw(shared_edge(s, i, f.window), x0, y0)
                                      : edge_raw(s.edge[i], x0, y0);
    // A hard edge (no fringe) tests D >= 0; one that does not own its ties
    // starts 1 LSB low, so it tests D > 0 and a pixel on a shared edge is drawn once.
    const bool hard = f.q == 0 || flagged;
    if (params_.fill_top_left && hard && !owns_ties(d)) d.v -= 1;
    if (params_.far_edges_constant) {
      switch (edge_over_box(d, x0, y0, box, hard ? 0 : q_raw)) {
        case BoxSide::kInside:  // never tested false here: a constant that cannot wrap
          d = EdgeRaw{};
          out.hard_edges |= static_cast<uint8_t>(1u << i);  // no fringe either: D = 0 is inside, n = 1
          ++counts_.constant_edges;
          break;
        case BoxSide::kOutside:
          ++counts_.off_window;
          return PrepareResult::kOffWindow;
        case BoxSide::kCrosses:
          break;
      }
    }
    EpInit& ep = out.ep[kEpD1 + i];
    const int clamped = !fit(d.v, ep.v) + !fit(d.dx, ep.dx) + !fit(d.dy, ep.dy);
    counts_.clamps[kEpD1 + i] += clamped;
    out.clamped = out.clamped || clamped > 0;
  }
  // T is carried on a 0..256 scale so that its 8-bit output saturates to 255 = 1.0.
  const double attr_scale[kAttrCount] = {1, 1, 1, 256, 1};
  const Ep attr_ep[kAttrCount] = {kEpR, kEpG, kEpB, kEpT, kEpZ};
  const FixFormat* attr_fmt[kAttrCount] = {&params_.ep_color, &params_.ep_color, &params_.ep_color,
                                           &params_.ep_t, &params_.ep_z};
  const WalkBox walk{x0, y0, box, f.q};
  std::optional<EmitRegion> region;  // preparer.steep_attributes limited: found once, for the planes that need it
  for (int a = 0; a < kAttrCount; ++a) {
    const AttributePlane& pl = s.attr[a];
    const double k = attr_scale[a];
    SteepPlane plane{k * pl.at(x0, y0), k * pl.dx, k * pl.dy};
    if (params_.steep_limited && !fits_walk_box(plane, *attr_fmt[a], walk)) {
      if (!region) region = emit_region(s, walk);
      if (limit_steep_plane(plane, k * pl.at(region->centroid.x, region->centroid.y), *attr_fmt[a], walk, *region))
        ++counts_.limited_planes;
    }
    convert(plane.v, plane.dx, plane.dy, *attr_fmt[a], out.ep[attr_ep[a]]);
  }
  ++counts_.prepared;
  return PrepareResult::kReady;
}

}  // namespace girtd
