// A `girtd sweep` spec (sim/io/sweep_spec.hpp).
#include "fuzz_input.hpp"
#include "io/sweep_spec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = girtd::fuzz::as_file(data, size, "fuzz_sweep.json");
  // The reader admits the names it is given (the registry's, in girtd); the
  // registry itself is not linked into the fuzz targets (it brings SystemC).
  girtd::fuzz::expect_only_input_errors([&] { girtd::read_sweep_spec(path, {"approx", "rtl"}); });
  return 0;
}
