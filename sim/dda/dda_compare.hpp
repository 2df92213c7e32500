// Golden DDA against the RTL DDA on one parameter set: every pixel (X, Y,
// R, G, B, Z, nf) and the clock it leaves, and the total clock count.
#pragma once

#include <string>
#include <vector>

#include "dda/dda_engine.hpp"
#include "dda/dda_rtl.hpp"

namespace girtd {

struct DdaComparison {
  bool match = true;
  std::string first_difference;  // empty when they match
  DdaRunStats golden;
  DdaRtlResult rtl;
  std::vector<Pixel> golden_pixels, rtl_pixels;  // for the frame check
};

DdaComparison compare_dda(const DdaEngine& golden, DdaRtl& rtl, const DdaParams& d, const DdaRtlOptions& opt);

}  // namespace girtd
