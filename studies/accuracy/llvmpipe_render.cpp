// Loads the llvmpipe module (llvmpipe_module.cpp) the first time a study
// draws with it: from beside this executable, else from the main build an
// RTL variant was built against.
#include "accuracy/llvmpipe_render.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "io/subprocess.hpp"

namespace girtd {

namespace {

using Entry = void (*)(const std::vector<Triangle>&, int, int, Rgb, uint16_t, LlvmpipeFrame&, std::string&);
constexpr const char* kModule = "libgirtd_llvmpipe.so";

Entry load() {
  namespace fs = std::filesystem;
  std::string tried;
  for (const fs::path& dir : {fs::path(self_executable()).parent_path(), fs::path(GIRTD_MAIN_BIN_DIR)}) {
    const fs::path path = dir / kModule;
    if (void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL))
      if (void* entry = dlsym(module, "girtd_llvmpipe_draw")) return reinterpret_cast<Entry>(entry);
    const char* why = dlerror();
    tried += (tried.empty() ? "" : "; ") + path.string() + (why ? std::string(": ") + why : std::string());
  }
  throw std::runtime_error("cannot load Mesa's llvmpipe (" + tried + ")");
}

}  // namespace

LlvmpipeFrame render_llvmpipe(const std::vector<Triangle>& triangles, int width, int height, Rgb background,
                              uint16_t z_clear) {
  static const Entry entry = load();
  LlvmpipeFrame frame;
  std::string error;
  entry(triangles, width, height, background, z_clear, frame, error);
  if (!error.empty()) throw std::runtime_error(error);
  return frame;
}

}  // namespace girtd
