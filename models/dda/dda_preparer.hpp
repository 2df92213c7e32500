// The DDA preparer (§3, 4.3.3): float triangle in, fixed-point parameter set
// out. Winding, edge equations and the start point come from the shared
// triangle setup; this adds the integer start pixel and limits and the
// conversion to the EP formats of config/girtd.json.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "common/triangle_setup.hpp"
#include "common/types.hpp"
#include "config/params.hpp"
#include "dda/dda_params.hpp"

namespace girtd {

enum class PrepareResult { kReady, kDegenerate, kOffWindow, kNoLatticeRow };

struct PreparerCounts {
  uint64_t prepared = 0, degenerate = 0, off_window = 0, no_lattice_row = 0;
  std::array<uint64_t, kEpCount> clamps{};  // start values and derivatives that did not fit the EP
  uint64_t constant_edges = 0;  // preparer.far_edges constant: edges sent as constants
  uint64_t limited_planes = 0;  // preparer.steep_attributes limited: attribute planes cut across
  uint64_t clamped_values() const {
    uint64_t n = 0;
    for (uint64_t c : clamps) n += c;
    return n;
  }
};

class DdaPreparer {
 public:
  explicit DdaPreparer(const Params& p) : params_(p) {}

  // Fills `out` and returns kReady, or says why the triangle was discarded.
  PrepareResult prepare(const Triangle& t, const FrameSettings& f, DdaParams& out);
  const PreparerCounts& counts() const { return counts_; }

 private:
  struct EdgeRaw {
    int64_t v = 0, dx = 0, dy = 0;
  };
  enum class BoxSide { kInside, kOutside, kCrosses };
  EdgeRaw edge_raw(const EdgeEquation& e, int x0, int y0) const;
  EdgeRaw shared_edge_raw(const SharedEdge& e, int x0, int y0) const;
  static bool owns_ties(const EdgeRaw& d);
  static BoxSide edge_over_box(const EdgeRaw& d, int x0, int y0, const PixelBox& box, int64_t q_raw);
  bool fit(int64_t raw, int64_t& reg) const;  // clamps into the D format; false when it did not fit

  const Params& params_;
  PreparerCounts counts_;
};

}  // namespace girtd
