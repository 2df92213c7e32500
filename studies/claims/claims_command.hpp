// girtd claims: the thesis' claims against measurements. Returns the process exit code (docs/interface.md):
// 0 success, 1 a check failed, 2 bad input or usage (InputError).
#pragma once

#include <string>

#include "cli/config_loader.hpp"

namespace girtd {

// campaign_only: the rows read from the study campaign's stored results.
int run_claims(const ConfigFiles& config, bool campaign_only = false);

}  // namespace girtd
