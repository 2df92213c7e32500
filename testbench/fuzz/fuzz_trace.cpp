// The trace reader, every level: the header names the level, as for a user.
#include <sstream>

#include "config/params.hpp"
#include "fuzz_input.hpp"
#include "io/trace_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const girtd::Params params = girtd::Params::defaults();
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  girtd::fuzz::expect_only_input_errors([&] { girtd::read_trace(in, "fuzz.trace", std::nullopt, params); });
  return 0;
}
