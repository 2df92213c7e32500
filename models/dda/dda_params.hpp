// The parameter set the preparer hands the DDA (one triangle): start pixel,
// limits, and for each of the 8 adder EPs its start value and x/y
// derivatives as raw fixed-point register contents. This is the DDA-level
// trace record.
#pragma once

#include <array>
#include <cstdint>

namespace girtd {

enum Ep { kEpR = 0, kEpG, kEpB, kEpT, kEpZ, kEpD1, kEpD2, kEpD3, kEpCount };

inline constexpr const char* kEpNames[kEpCount] = {"R", "G", "B", "T", "Z", "D1", "D2", "D3"};

struct EpInit {
  int64_t v = 0, dx = 0, dy = 0;
  bool operator==(const EpInit& o) const { return v == o.v && dx == o.dx && dy == o.dy; }
};

struct DdaParams {
  int x0 = 0, y0 = 0;  // start pixel
  int xmin = 0, xmax = 0, ymax = 0;
  std::array<EpInit, kEpCount> ep{};
  double q = 1.0;  // Norm width: 0 or 2^k (the Norm unit is a shift)
  uint8_t hard_edges = 0;  // bit i: D(i+1) has no fringe, its Norm is as at Q = 0 (edge flags)
  int source_line = 0;
  bool clamped = false;  // the preparer clamped a value to its EP (not in traces)
  int layer = -1;        // seam_layer() of the triangle (not hardware, not in traces: for counting seams)

  bool operator==(const DdaParams& o) const {
    return x0 == o.x0 && y0 == o.y0 && xmin == o.xmin && xmax == o.xmax && ymax == o.ymax &&
           ep == o.ep && q == o.q && hard_edges == o.hard_edges;
  }
};

}  // namespace girtd
