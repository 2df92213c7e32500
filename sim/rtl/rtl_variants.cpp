#include "rtl/rtl_variants.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "config/rtl_package.hpp"
#include "io/subprocess.hpp"
#include "rtl/rtl_build_info.hpp"

namespace girtd {

namespace fs = std::filesystem;

namespace {

// Held while a variant is configured and built: parallel runs of one sweep
// ask for the same variant at once, and one of them builds it.
class FileLock {
 public:
  explicit FileLock(const fs::path& path) : fd_(::open(path.c_str(), O_CREAT | O_RDWR, 0644)) {
    if (fd_ < 0 || flock(fd_, LOCK_EX) != 0) throw std::runtime_error("cannot lock " + path.string());
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

std::string last_lines(const fs::path& log, int n) {
  std::ifstream in(log);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::string out;
  for (size_t i = lines.size() > size_t(n) ? lines.size() - n : 0; i < lines.size(); ++i) out += "  " + lines[i] + "\n";
  return out;
}

// True when ninja has something to do for the variant's girtd.
bool out_of_date(const fs::path& dir) {
  const fs::path dry = dir / "dry_run.txt";
  fs::remove(dry);
  if (run_process_logged({"ninja", "-C", dir.string(), "-n", "girtd"}, dry.string()) != 0) return true;
  std::ifstream in(dry);
  std::stringstream text;
  text << in.rdbuf();
  return text.str().find("no work to do") == std::string::npos;
}

}  // namespace

std::string rtl_variants_dir() {
  if (const char* dir = std::getenv("GIRTD_VARIANTS_DIR"); dir && *dir) return dir;
  return std::string(GIRTD_MAIN_BUILD_DIR) + "/variants";
}

void run_in_rtl_variant_if_needed(const Params& p, char** argv) {
  const std::string key = rtl_build_key(p);
  if (key == built_rtl_key()) return;
  const fs::path dir = fs::path(rtl_variants_dir()) / key;
  const fs::path exe = dir / "bin" / "girtd", log = dir / "build.log";
  fs::create_directories(dir);
  {
    FileLock lock(dir.string() + ".lock");
    const std::string why = rtl_build_differences(nlohmann::json::parse(built_rtl_values()), rtl_build_values(p));
    bool build = false;
    if (!fs::exists(dir / "build.ninja")) {
      std::fprintf(stderr,
                   "girtd: building an RTL variant for %s in %s (once: later runs with these values reuse it; "
                   "a few minutes, log in build.log)\n",
                   why.c_str(), dir.c_str());
      // The whole merged configuration: the generator checks it as a unit.
      std::ofstream(dir / "config.json") << p.source.dump(2) << "\n";
      const int rc = run_process_logged({"cmake", "-S", GIRTD_SOURCE_DIR, "-B", dir.string(), "-G", "Ninja",
                                         "-DCMAKE_BUILD_TYPE=Release", "-DGIRTD_RTL_VARIANT_OF=" GIRTD_MAIN_BUILD_DIR,
                                         "-DGIRTD_RTL_CONFIG=" + (dir / "config.json").string()},
                                        log.string());
      if (rc != 0) {
        fs::remove(dir / "build.ninja");  // configure again next time
        throw std::runtime_error("configuring the RTL variant " + key + " failed (" + log.string() + "):\n" +
                                 last_lines(log, 12));
      }
      build = true;
    } else if (out_of_date(dir)) {
      std::fprintf(stderr, "girtd: updating the RTL variant %s (%s): its sources or the main build changed\n",
                   key.c_str(), why.c_str());
      build = true;
    }
    if (build && run_process_logged({"cmake", "--build", dir.string(), "--target", "girtd"}, log.string()) != 0)
      throw std::runtime_error("building the RTL variant " + key + " failed (" + log.string() + "):\n" +
                               last_lines(log, 12));
  }
  std::fflush(stdout);
  std::fflush(stderr);
  execv(exe.c_str(), argv);
  throw std::runtime_error("cannot run the RTL variant " + exe.string());
}

}  // namespace girtd
