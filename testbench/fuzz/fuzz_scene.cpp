// Scene JSON. The scene is written into scratch()/scenes/, beside a link
// models -> traces/models, so the seeds' model paths resolve as they do in
// the repository.
#include <filesystem>

#include "config/params.hpp"
#include "fuzz_input.hpp"
#include "io/scene_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace fs = std::filesystem;
  static const girtd::Params params = girtd::Params::defaults();
  static const bool linked = [] {
    fs::create_directories(girtd::fuzz::scratch() / "scenes");
    fs::create_directory_symlink(fs::path(GIRTD_SOURCE_DIR) / "traces" / "models",
                                 girtd::fuzz::scratch() / "models");
    return true;
  }();
  (void)linked;
  const std::string path = girtd::fuzz::as_file(data, size, "scenes/fuzz.json");
  girtd::fuzz::expect_only_input_errors([&] { girtd::read_scene(path, params); });
  return 0;
}
