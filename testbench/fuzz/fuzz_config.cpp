// A --config file merged over config/girtd.json.
#include "config/params.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = girtd::fuzz::as_file(data, size, "fuzz_config.json");
  girtd::fuzz::expect_only_input_errors([&] { girtd::Params::from_files({path}); });
  return 0;
}
