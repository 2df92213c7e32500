// Where a run's numbers left their EP's format (docs/design.md §4), counted per
// EP: a wrapped value in use (the register kept the low bits of a sum past
// its range, at a clock that reads it: D1..D3 where the sequencer tests the
// edges, R, G, B, T, Z at emission; an edge function that wrapped puts
// pixels on the wrong side),
// an output clipped to its range at emission (by design, counted for
// information), and a start value or derivative the preparer clamped.
// report.json `numerics`.
#pragma once

#include <array>
#include <cstdint>

#include "dda/dda_params.hpp"

namespace girtd {

struct EpLimits {
  uint64_t wraps = 0;        // D1..D3: clocks that read a wrapped value; the others: pixels emitted with one
  uint64_t saturations = 0;  // pixels whose output clipped (clamps: the preparer's PreparerCounts)
};

struct EpNumerics {
  std::array<EpLimits, kEpCount> ep{};
  uint64_t triangles_affected = 0;  // triangles with a wrap or a clamp
  uint64_t first_affected = 0;      // the first of them, numbered from 1 among the triangles drawn (0: none)
  int first_affected_line = 0;      // its line in the input (0: not known)

  uint64_t wraps() const {
    uint64_t n = 0;
    for (const EpLimits& e : ep) n += e.wraps;
    return n;
  }
  // `one`: a single triangle's counts; `drawn_before`: triangles drawn before it.
  void add_triangle(const EpNumerics& one, uint64_t drawn_before) {
    for (int i = 0; i < kEpCount; ++i) {
      ep[i].wraps += one.ep[i].wraps;
      ep[i].saturations += one.ep[i].saturations;
    }
    if (one.triangles_affected && !first_affected) {
      first_affected = drawn_before + 1;
      first_affected_line = one.first_affected_line;
    }
    triangles_affected += one.triangles_affected;
  }
};

}  // namespace girtd
