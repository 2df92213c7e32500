#include "rtl/rtl_build_info.hpp"

#include "rtl_build.hpp"

namespace girtd {

const char* built_rtl_key() { return kRtlBuildKey; }
const char* built_rtl_values() { return kRtlBuildValues; }

}  // namespace girtd
