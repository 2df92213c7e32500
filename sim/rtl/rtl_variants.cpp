#include "rtl/rtl_variants.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "common/file_text.hpp"
#include "layout/rtl_package.hpp"
#include "rtl/rtl_build_info.hpp"

namespace girtd {

namespace fs = std::filesystem;

namespace {

// Which main build (and sanitizer mode) a variant links with, its fields
// joined by `sep`; a variant configured for another is configured again.
std::string main_build_fields(char sep) {
  return std::string(GIRTD_MAIN_BUILD_DIR) + sep + (GIRTD_MAIN_SANITIZED ? "1" : "0");
}

// This executable's identity (modification time and size): a variant built
// before the main build changed links the old libraries, and is not run.
std::string build_id() {
  struct stat st {};
  if (stat("/proc/self/exe", &st) != 0) return "unknown";
  return std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec) + ":" +
         std::to_string(st.st_size);
}

// What the driver writes into DIR/built_for.txt once the build succeeded.
std::string built_stamp() { return main_build_fields(' ') + " " + build_id(); }

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace

std::string rtl_variants_dir() {
  if (const char* dir = std::getenv("GIRTD_VARIANTS_DIR"); dir && *dir) return fs::absolute(dir).string();
  return std::string(GIRTD_MAIN_BUILD_DIR) + "/variants";
}

std::optional<RtlVariant> needed_rtl_variant(const Params& p) {
  const std::string key = rtl_build_key(p);
  if (key == built_rtl_key()) return std::nullopt;
  return RtlVariant{key, (fs::path(rtl_variants_dir()) / key).string(),
                    rtl_build_differences(nlohmann::json::parse(built_rtl_values()), rtl_build_values(p))};
}

std::string rtl_variant_plan_line(const RtlVariant& v, const Params& p) {
  fs::create_directories(v.dir);
  // The whole merged configuration: the generator checks it as a unit. Any
  // configuration with this key elaborates the same RTL, and the variant's
  // build configures again when the file changes: it is written once.
  const fs::path config = fs::path(v.dir) / "config.json";
  if (!fs::exists(config)) {
    const fs::path tmp = config.string() + ".tmp" + std::to_string(getpid());
    std::ofstream(tmp) << p.source.dump(2) << "\n";
    fs::rename(tmp, config);
  }
  return "variant\t" + v.key + "\t" + v.dir + "\t" + v.why + "\t" + main_build_fields('\t') + "\t" + build_id();
}

void run_in_rtl_variant_if_needed(const Params& p, char** argv) {
  const std::optional<RtlVariant> v = needed_rtl_variant(p);
  if (!v) return;
  const fs::path exe = fs::path(v->dir) / "bin" / "girtd";
  // A variant that does not hold what it was built for would start itself again.
  if (const char* running = std::getenv("GIRTD_RTL_VARIANT"); running && v->key == running)
    throw std::runtime_error("the RTL variant in " + v->dir + " holds the elaboration " + built_rtl_key() +
                             ", not " + v->key + ": remove that folder and build it again");
  if (trimmed(read_file_text((fs::path(v->dir) / "built_for.txt").string()).value_or("")) != built_stamp() ||
      !fs::exists(exe))
    throw MissingPrerequisite("this configuration needs the RTL elaborated for " + v->why + " (variant " + v->key +
                              "), not built for this build of girtd: tools/girtd builds it before running the " +
                              "command (`tools/girtd variant COMMAND ARGS...` builds it alone)");
  std::fflush(stdout);
  std::fflush(stderr);
  setenv("GIRTD_RTL_VARIANT", v->key.c_str(), 1);
  execv(exe.c_str(), argv);
  throw std::runtime_error("cannot run the RTL variant " + exe.string());
}

}  // namespace girtd
