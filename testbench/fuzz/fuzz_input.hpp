// What every fuzz target shares: the input as a file (the readers take
// paths, as the CLI hands them), and the rule that bad input may only ever
// be an InputError. Anything else escaping (another exception, a crash, a
// sanitizer report, a leak) is a bug the fuzzer reports.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/input_error.hpp"

namespace girtd::fuzz {

// A scratch folder of this process, removed at exit.
inline const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    std::string tmpl = (std::filesystem::temp_directory_path() / "girtd_fuzz_XXXXXX").string();
    if (!mkdtemp(tmpl.data())) std::abort();
    std::atexit([] { std::filesystem::remove_all(scratch()); });
    return std::filesystem::path(tmpl);
  }();
  return dir;
}

// Writes the input to scratch()/NAME and returns the path.
inline std::string as_file(const uint8_t* data, size_t size, const std::string& name) {
  const std::string path = (scratch() / name).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                static_cast<std::streamsize>(size));
  return path;
}

// Runs f; bad input is expected and must be an InputError with a message.
template <typename F>
void expect_only_input_errors(F f) {
  try {
    f();
  } catch (const InputError& e) {
    if (std::string(e.what()).empty()) std::abort();  // an error must say what is wrong
  }
}

}  // namespace girtd::fuzz
