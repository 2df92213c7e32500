// A model file: the pre-check of its format, then assimp and the checks on
// what it returns, in this process (import_model runs assimp in a child,
// where the fuzzer would not see its coverage). Built once per format;
// GIRTD_FUZZ_MODEL_EXT names it.
#include "fuzz_input.hpp"
#include "io/model_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = girtd::fuzz::as_file(data, size, std::string("fuzz") + GIRTD_FUZZ_MODEL_EXT);
  std::vector<std::string> warnings;
  girtd::fuzz::expect_only_input_errors([&] { girtd::import_model_in_process(path, warnings); });
  return 0;
}
