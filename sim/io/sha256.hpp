// SHA-256 (OpenSSL) as lower-case hex: the report's image_sha256, and the
// names of configurations.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config/params.hpp"

namespace girtd {

std::string sha256_hex(const std::vector<uint8_t>& bytes);
std::string sha256_hex(const std::string& text);

// A configuration's identity: the first 16 hex digits of the SHA-256 of the
// merged configuration. Expectations are compared only under the
// configuration they were blessed with; a sweep's point is named by it.
std::string config_key(const Params& params);

}  // namespace girtd
