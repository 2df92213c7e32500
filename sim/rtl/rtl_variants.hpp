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
#include <stdexcept>
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

// One line of `girtd --plan`: "variant KEY DIR WHY MAIN SANITIZED BUILD_ID"
// (tab-separated; MAIN: this build's folder, SANITIZED: 0 or 1, BUILD_ID:
// this executable's identity, which the driver stamps a built variant with).
// Writes a configuration with these RTL values into DIR/config.json, the
// file the variant is generated from, when there is none.
std::string rtl_variant_plan_line(const RtlVariant& v, const Params& p);

// The exit code of a run that needs what the driver makes (an RTL variant)
// and finds it missing or built against another main build.
inline constexpr int kExitMissingPrerequisite = 4;
class MissingPrerequisite : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Returns when this executable holds the elaboration `p` needs. Otherwise
// replaces this process by the variant, run with the same `argv` (does not
// return), or throws MissingPrerequisite when the driver has not built it
// against this executable.
void run_in_rtl_variant_if_needed(const Params& p, char** argv);

// GIRTD_VARIANTS_DIR, or the main build's variants/ folder.
std::string rtl_variants_dir();

}  // namespace girtd
