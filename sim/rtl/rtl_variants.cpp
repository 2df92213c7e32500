#include "rtl/rtl_variants.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "common/file_text.hpp"
#include "layout/rtl_package.hpp"
#include "io/subprocess.hpp"
#include "rtl/rtl_build_info.hpp"

namespace girtd {

namespace fs = std::filesystem;

namespace {

// Held while a variant is configured and built: parallel runs of one sweep
// ask for the same variant at once, and one of them builds it.
class FileLock {
 public:
  FileLock(const fs::path& path, const std::string& waiting) : fd_(::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644)) {
    if (fd_ < 0) throw std::runtime_error("cannot open the lock " + path.string());
    if (flock(fd_, LOCK_EX | LOCK_NB) == 0) return;
    std::fprintf(stderr, "%s\n", waiting.c_str());
    if (flock(fd_, LOCK_EX) != 0) {
      ::close(fd_);
      throw std::runtime_error("cannot lock " + path.string());
    }
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

std::string read_text(const fs::path& path) { return read_file_text(path.string()).value_or(""); }

// True when ninja has something to do for the variant's girtd.
bool out_of_date(const fs::path& dir) {
  const fs::path dry = dir / "dry_run.txt";
  fs::remove(dry);
  if (run_process_logged({"ninja", "-C", dir.string(), "-n", "girtd"}, dry.string()) != 0) return true;
  return read_text(dry).find("no work to do") == std::string::npos;
}

// Which main build (and sanitizer mode) a variant links with: one that was
// configured for another is configured again.
std::string main_build_stamp() {
  return std::string(GIRTD_MAIN_BUILD_DIR) + (GIRTD_MAIN_SANITIZED ? " sanitized" : "") + "\n";
}

}  // namespace

std::string rtl_variants_dir() {
  if (const char* dir = std::getenv("GIRTD_VARIANTS_DIR"); dir && *dir) return fs::absolute(dir).string();
  return std::string(GIRTD_MAIN_BUILD_DIR) + "/variants";
}

void run_in_rtl_variant_if_needed(const Params& p, char** argv) {
  const std::string key = rtl_build_key(p);
  if (key == built_rtl_key()) return;
  const fs::path dir = fs::path(rtl_variants_dir()) / key;
  const fs::path exe = dir / "bin" / "girtd", log = dir / "build.log";
  // A variant that does not hold what it was built for would start itself again.
  if (const char* running = std::getenv("GIRTD_RTL_VARIANT"); running && key == running)
    throw std::runtime_error("the RTL variant in " + dir.string() + " holds the elaboration " + built_rtl_key() +
                             ", not " + key + ": remove that folder to build it again");
  fs::create_directories(dir);
  {
    FileLock lock(dir.string() + ".lock", "girtd: waiting for another girtd that is building the RTL variant " + key);
    const std::string why = rtl_build_differences(nlohmann::json::parse(built_rtl_values()), rtl_build_values(p));
    if (read_text(dir / "main_build.txt") != main_build_stamp()) {  // never configured, or for another build
      fs::remove(dir / "build.ninja");
      fs::remove(dir / "CMakeCache.txt");
    }
    bool build = false;
    if (!fs::exists(dir / "build.ninja")) {
      std::fprintf(stderr,
                   "girtd: building an RTL variant for %s in %s (once: later runs with these values reuse it; "
                   "a few minutes, log in build.log)\n",
                   why.c_str(), dir.c_str());
      // The whole merged configuration: the generator checks it as a unit.
      std::ofstream(dir / "config.json") << p.source.dump(2) << "\n";
      std::vector<std::string> configure = {"cmake", "-S", GIRTD_SOURCE_DIR, "-B", dir.string(), "-G", "Ninja",
                                            "-DCMAKE_BUILD_TYPE=Release", "-DGIRTD_RTL_VARIANT_OF=" GIRTD_MAIN_BUILD_DIR,
                                            "-DGIRTD_RTL_CONFIG=" + (dir / "config.json").string()};
      if (GIRTD_MAIN_SANITIZED) configure.push_back("-DGIRTD_SANITIZE=ON");
      const int rc = run_process_logged(configure, log.string());
      if (rc != 0) {
        fs::remove(dir / "build.ninja");  // configure again next time
        throw std::runtime_error("configuring the RTL variant " + key + " failed (" + log.string() + "):\n" +
                                 last_lines(log, 12));
      }
      std::ofstream(dir / "main_build.txt") << main_build_stamp();
      build = true;
    } else if (out_of_date(dir)) {
      std::fprintf(stderr, "girtd: updating the RTL variant %s (%s): its sources or the main build changed\n",
                   key.c_str(), why.c_str());
      build = true;
    }
    if (build && run_process_logged({"cmake", "--build", dir.string(), "--target", "girtd"}, log.string()) != 0) {
      fs::remove(dir / "build.ninja");  // configure afresh next time
      throw std::runtime_error("building the RTL variant " + key + " failed (" + log.string() + "):\n" +
                               last_lines(log, 12));
    }
  }
  std::fflush(stdout);
  std::fflush(stderr);
  setenv("GIRTD_RTL_VARIANT", key.c_str(), 1);
  execv(exe.c_str(), argv);
  throw std::runtime_error("cannot run the RTL variant " + exe.string());
}

}  // namespace girtd
