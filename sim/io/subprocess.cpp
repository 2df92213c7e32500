#include "io/subprocess.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <thread>
#include <stdexcept>

namespace girtd {

int run_process(const std::vector<std::string>& args, bool quiet) { return run_process_logged(args, quiet ? "/dev/null" : ""); }

int run_process_logged(const std::vector<std::string>& args, const std::string& log_path) {
  return run_process_timed(args, log_path, 0);
}

namespace {

// Starts `args` with its output appended to `log_path` ("" keeps ours); its pid, or -1.
pid_t start(const std::vector<std::string>& args, const std::string& log_path, bool own_group) {
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid != 0) return pid;
  if (own_group) setpgid(0, 0);  // a timeout kills what it started too
  if (!log_path.empty()) {
    const int log = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (log >= 0) {
      dup2(log, 1);
      dup2(log, 2);
    }
  }
  execvp(argv[0], argv.data());
  _exit(127);
}

int exit_code(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  const int sig = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return sig == SIGINT || sig == SIGTERM || sig == SIGHUP ? kStopped : -1;
}

}  // namespace

ProcessUsage run_process_measured(const std::vector<std::string>& args, const std::string& log_path) {
  ProcessUsage u;
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = start(args, log_path, false);
  if (pid < 0) return u;
  int status = 0;
  rusage r{};
  pid_t done;
  while ((done = wait4(pid, &status, 0, &r)) < 0 && errno == EINTR) {
  }
  u.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (done != pid) return u;
  u.exit_code = exit_code(status);
  u.peak_rss_mb = double(r.ru_maxrss) / 1024.0;  // KiB on Linux
  return u;
}

int run_process_timed(const std::vector<std::string>& args, const std::string& log_path, double timeout_s) {
  const pid_t pid = start(args, log_path, timeout_s > 0);
  if (pid < 0) return -1;
  int status = 0;
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const pid_t done = waitpid(pid, &status, timeout_s > 0 ? WNOHANG : 0);
    if (done < 0 && errno == EINTR) continue;  // a signal to us (a sweep being stopped): the child is still there
    if (done < 0) return -1;
    if (done == pid) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout_s) {
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      return kTimedOut;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return exit_code(status);
}

std::string self_executable() {
  std::vector<char> buf(4096);
  const ssize_t n = readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) throw std::runtime_error("cannot find the girtd executable (/proc/self/exe)");
  return std::string(buf.data(), static_cast<size_t>(n));
}

}  // namespace girtd
