// The registry of back ends: one entry each for reference, golden, approx
// and rtl, with what it can do (capabilities), the options it refuses and
// its factory. The CLI's choices, the report, accuracy, sweeps and benches
// ask it; no other code branches on a back end's name.
#pragma once

#include <string>
#include <vector>

#include "backends/backend_entry.hpp"

namespace girtd {

// Every back end, in the order --help lists them.
const std::vector<BackendEntry>& backend_registry();
std::vector<std::string> backend_names();

// The entry named `name`; nullptr for an unknown name.
const BackendEntry* find_backend(const std::string& name);
// The entry named `name`; std::logic_error for an unknown one (the CLI
// admits only backend_names()).
const BackendEntry& backend_named(const std::string& name);
// The one back end with capability `c` (kExactPicture, kExactTiming).
const BackendEntry& backend_with(Capability c);

// The registered report keys this back end cannot know (report_keys.hpp).
std::vector<std::string> not_modeled(const BackendEntry& b);

}  // namespace girtd
