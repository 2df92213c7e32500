// The EPs' fraction bits against the thesis' error budget (§4.2.8): the
// error of an EP's adder after N steps in one direction from the start
// pixel, the start value and the derivatives rounded by the preparer, for
// random triangles. The error of a plane after i steps in X and j in Y is
// linear in (i, j), so over every pixel within N steps (|i| + |j| <= N) it
// peaks at one of the four corners (+-N, 0), (0, +-N): those are evaluated,
// as sums of the raw register values (no wrap or saturation: the error of
// the adds, not of the formats' range). Unlike claims/ep_error.hpp
// (the DDA's own walk, pixel by pixel) this costs a few operations per
// triangle, so every width can be tried.
#pragma once

#include <array>
#include <string>

#include "config/params.hpp"
#include "girtd/design_constants.hpp"

namespace girtd {

enum class EpKind { kColor, kT, kZ, kD };
inline constexpr std::array<EpKind, 4> kEpKinds = {EpKind::kColor, EpKind::kT, EpKind::kZ, EpKind::kD};
const char* ep_key(EpKind ep);  // "color", "t", "z", "d" (config ep.<key>)
FixFormat& ep_format(Params& p, EpKind ep);

// The budget: 1 LSB of the output (colour, T, Z), 0.125 px of edge distance
// (D), for the derivatives' rounding over N steps; the start value's own
// rounding, half an LSB of the fraction, comes on top (the thesis' 1,024-step
// argument counts the derivatives alone; docs/design.md §4 asks to state the
// bound): ep_bound = budget + 2^-(frac_bits + 1).
double ep_budget(EpKind ep);
double ep_bound(EpKind ep, int frac_bits);
const char* ep_unit(EpKind ep);

// The thesis' argument steps an EP across the screen (its width: 1,024
// steps); across and down (width + height) is a walk from corner to corner.
inline constexpr int kAcrossSteps = kScreenWidth, kCornerSteps = kScreenWidth + kScreenHeight;
// The largest triangle the random samples draw: one pixel short of the screen.
inline constexpr int kLargestTrianglePx = kScreenWidth - 1;

// Worst error in the EP's unit over `triangles` random triangles of up to
// kLargestTrianglePx, at N = `steps`.
double ep_error_after_steps(const Params& p, EpKind ep, int steps, int triangles = 2000, uint32_t seed = 4242);

struct EpPrecision {
  EpKind ep;
  int configured = 0;        // ep.<EP>.frac_bits of the configuration
  int fewest_across = -1;    // fewest fraction bits keeping the budget over kAcrossSteps (-1: none tried)
  int fewest_corner = -1;    // over kCornerSteps
  double error_across = 0;   // the configured width's errors
  double error_corner = 0;
};

// Tries fraction widths from the fewest the configuration allows (1; D: the
// Norm unit's nf.norm_frac_bits) to configured + 8, int_bits unchanged.
EpPrecision ep_precision(const Params& p, EpKind ep);

}  // namespace girtd
