// RTL variants on demand. The Verilated RTL is elaborated for its widths,
// layouts and depths (models/layout/rtl_package.hpp: rtl_build_values); a
// run whose configuration asks for others runs in a girtd built for them,
// DIR/KEY/bin/girtd (DIR: rtl_variants_dir(), KEY: rtl_build_key). It is
// built once, with a line on stderr saying so and why, reused by later runs
// and sweep points, and brought up to date by ninja when the sources or the
// main build change. It links the main build's libraries and compiles only
// the RTL and the files that include its headers (cmake/GirtdRtlModel.cmake).
#pragma once

#include <string>

#include "config/params.hpp"

namespace girtd {

// Returns when this executable holds the elaboration `p` needs. Otherwise
// builds (or updates) the variant and replaces this process by it, run with
// the same `argv` (does not return).
void run_in_rtl_variant_if_needed(const Params& p, char** argv);

// GIRTD_VARIANTS_DIR, or the main build's variants/ folder.
std::string rtl_variants_dir();

}  // namespace girtd
