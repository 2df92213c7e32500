// What the Verilated RTL is elaborated with, and the files that tell it:
// the SystemVerilog package (widths, the FIFO word's fields, the page
// geometry, the DDA's state encoding), the U >= 2 product PROM table, and
// the C++ header that records which values a build has. Written by
// girtd_gen_rtl (models/layout/gen_rtl_main.cpp) for the default build and
// for every RTL variant (sim/rtl/rtl_variants.hpp).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "config/params.hpp"

namespace girtd {

// The configuration values a Verilated build is elaborated with (a change
// needs another build); everything else is a run-time input of the RTL.
nlohmann::json rtl_build_values(const Params& p);
// A short name for those values (16 hex digits of their FNV-1a hash).
std::string rtl_build_key(const Params& p);
std::string rtl_build_key(const nlohmann::json& build_values);
// "ep.color.frac_bits 9 -> 7, fifo.max_depth 32 -> 64": what differs.
std::string rtl_build_differences(const nlohmann::json& built, const nlohmann::json& wanted);

std::string sv_package_text(const Params& p);
std::string sv_prom_table_text(const Params& p);
std::string rtl_build_header_text(const Params& p);

}  // namespace girtd
