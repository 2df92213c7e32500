// Golden-vs-RTL regression of the DDA over traces and random triangles:
// per primitive the pixel streams (values and clocks) and clock counts, per
// frame the pictures the golden HAD builds from either stream. Shared by
// `girtd regress` and the check-build harness in testbench/rtl.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config/params.hpp"
#include "dda/dda_rtl.hpp"

namespace girtd {
class BackendRtl;
}

namespace girtd {

struct RegressionRow {
  std::string name;
  uint64_t triangles = 0, pixels = 0, clocks = 0, stalls = 0;
  uint64_t ticks = 0;  // base ticks the RTL back end took (0 without it)
  std::string failure;  // empty: passed
};

// `stall` is the back-pressure probability applied to every other triangle;
// `backend` (may be null) also runs the whole RTL back end and checks its frames.
RegressionRow regress_trace(const std::string& path, const Params& p, DdaRtl& rtl, BackendRtl* backend, double stall);
RegressionRow regress_random(int count, uint32_t seed, const Params& p, DdaRtl& rtl, BackendRtl* backend,
                             double stall);

// Every trace file under `dir` (recursively) with a girtd-trace header, sorted.
std::vector<std::string> traces_under(const std::string& dir);

}  // namespace girtd
