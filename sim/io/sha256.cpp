#include "io/sha256.hpp"

#include <openssl/evp.h>

#include <stdexcept>

namespace girtd {

std::string sha256_hex(const std::vector<uint8_t>& bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int len = 0;
  if (!EVP_Digest(bytes.data(), bytes.size(), digest, &len, EVP_sha256(), nullptr))
    throw std::runtime_error("SHA-256 failed");
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < len; ++i) {
    out += hex[digest[i] >> 4];
    out += hex[digest[i] & 15];
  }
  return out;
}

std::string sha256_hex(const std::string& text) { return sha256_hex(std::vector<uint8_t>(text.begin(), text.end())); }

std::string config_key(const Params& params) { return sha256_hex(params.source.dump()).substr(0, 16); }

}  // namespace girtd
