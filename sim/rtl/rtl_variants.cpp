#include "rtl/rtl_variants.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "common/file_text.hpp"
#include "common/input_error.hpp"
#include "layout/rtl_package.hpp"
#include "rtl/rtl_build_info.hpp"

namespace girtd {

namespace fs = std::filesystem;

namespace {

// What a variant was built against: the driver writes this line into
// DIR/built_for.txt once its build succeeded; a variant of another main
// build (or sanitizer mode), or one whose build failed, is not run.
std::string main_build_stamp() {
  return std::string(GIRTD_MAIN_BUILD_DIR) + (GIRTD_MAIN_SANITIZED ? " sanitized" : "");
}

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
  const fs::path config = fs::path(v.dir) / "config.json";
  // The whole merged configuration: the generator checks it as a unit. The
  // build configures again when it changes, so it is written only then.
  const std::string text = p.source.dump(2) + "\n";
  if (read_file_text(config.string()) != text) {
    const fs::path tmp = config.string() + ".tmp" + std::to_string(getpid());
    std::ofstream(tmp) << text;
    fs::rename(tmp, config);
  }
  std::string defines = "-DCMAKE_BUILD_TYPE=Release -DGIRTD_RTL_VARIANT_OF=" GIRTD_MAIN_BUILD_DIR
                        " -DGIRTD_RTL_CONFIG=" + config.string();
  if (GIRTD_MAIN_SANITIZED) defines += " -DGIRTD_SANITIZE=ON";
  return "variant\t" + v.key + "\t" + v.dir + "\t" + v.why + "\t" + defines + "\t" + main_build_stamp();
}

void run_in_rtl_variant_if_needed(const Params& p, char** argv) {
  const std::optional<RtlVariant> v = needed_rtl_variant(p);
  if (!v) return;
  const fs::path exe = fs::path(v->dir) / "bin" / "girtd";
  // A variant that does not hold what it was built for would start itself again.
  if (const char* running = std::getenv("GIRTD_RTL_VARIANT"); running && v->key == running)
    throw std::runtime_error("the RTL variant in " + v->dir + " holds the elaboration " + built_rtl_key() +
                             ", not " + v->key + ": remove that folder and build it again");
  if (trimmed(read_file_text((fs::path(v->dir) / "built_for.txt").string()).value_or("")) != main_build_stamp() ||
      !fs::exists(exe))
    throw InputError("--config", 0,
                     "needs the RTL elaborated for " + v->why + " (variant " + v->key + "), which is not built: " +
                         "tools/girtd builds it before running this command (its step `tools/girtd variant " +
                         "COMMAND ARGS...` builds it alone)");
  std::fflush(stdout);
  std::fflush(stderr);
  setenv("GIRTD_RTL_VARIANT", v->key.c_str(), 1);
  execv(exe.c_str(), argv);
  throw std::runtime_error("cannot run the RTL variant " + exe.string());
}

}  // namespace girtd
