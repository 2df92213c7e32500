// Which elaboration of the RTL this executable holds: its build key and
// values (models/layout/rtl_package.hpp), for code that must not include
// the generated rtl_build.hpp itself (sim/rtl/rtl_variants.hpp).
#pragma once

namespace girtd {

const char* built_rtl_key();
const char* built_rtl_values();  // JSON

}  // namespace girtd
