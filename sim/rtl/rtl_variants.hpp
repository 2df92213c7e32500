// RTL variants. The Verilated RTL is elaborated for its widths, layouts and
// depths (models/layout/rtl_package.hpp: rtl_build_values); a run whose
// configuration asks for others runs in a girtd built for them,
// DIR/KEY/bin/girtd (DIR: rtl_variants_dir(), KEY: rtl_build_key). The
// simulator builds nothing: the driver (tools/girtd's variant step) asks
// `girtd --plan ...` which variants a command needs, configures and builds
// them (linking the main build's libraries, compiling only the RTL and what
// includes its headers: cmake/GirtdRtlModel.cmake) and stamps each one it
// built; this process then only runs in a stamped variant.
#pragma once

#include <optional>
#include <string>

#include "config/params.hpp"

namespace girtd {

struct RtlVariant {
  std::string key;  // rtl_build_key
  std::string dir;  // rtl_variants_dir()/key
  std::string why;  // the values that differ from this build's
};

// The variant `p` needs, or nothing when this executable holds its elaboration.
std::optional<RtlVariant> needed_rtl_variant(const Params& p);

// One line of `girtd --plan`: "variant KEY DIR WHY DEFINES" (tab-separated;
// DEFINES: the configure step's -D options, space-separated). Writes the
// merged configuration the variant is generated from into DIR/config.json.
std::string rtl_variant_plan_line(const RtlVariant& v, const Params& p);

// Returns when this executable holds the elaboration `p` needs. Otherwise
// replaces this process by the variant, run with the same `argv` (does not
// return), or throws InputError when the driver has not built it.
void run_in_rtl_variant_if_needed(const Params& p, char** argv);

// GIRTD_VARIANTS_DIR, or the main build's variants/ folder.
std::string rtl_variants_dir();

}  // namespace girtd
