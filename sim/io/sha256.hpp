// SHA-256 (OpenSSL) as lower-case hex: the report's image_sha256.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace girtd {

std::string sha256_hex(const std::vector<uint8_t>& bytes);

}  // namespace girtd
