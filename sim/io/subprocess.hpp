// Runs a program without a shell and waits for it.
#pragma once

#include <string>
#include <vector>

namespace girtd {

// argv[0] is looked up on PATH. Returns the exit code, kStopped if a
// SIGINT, SIGTERM or SIGHUP ended it (someone stopped it: not a crash), or -1
// if the program could not be started or ended otherwise (a crash). `quiet` sends its stdout
// and stderr to /dev/null.
inline constexpr int kStopped = -3;
int run_process(const std::vector<std::string>& argv, bool quiet);
// The same with its stdout and stderr appended to `log_path` ("" keeps ours).
int run_process_logged(const std::vector<std::string>& argv, const std::string& log_path);
// The same, killed after `timeout_s` seconds (0: never): returns kTimedOut then.
inline constexpr int kTimedOut = -2;
int run_process_timed(const std::vector<std::string>& argv, const std::string& log_path, double timeout_s);

// The same, timed: its exit code (as run_process's), its elapsed time and the
// peak resident memory of its largest process (the kernel's ru_maxrss of the
// child, which takes in its own reaped children).
struct ProcessUsage {
  int exit_code = -1;
  double elapsed_s = 0;
  double peak_rss_mb = 0;  // MiB
};
ProcessUsage run_process_measured(const std::vector<std::string>& argv, const std::string& log_path);

// This program's own path (/proc/self/exe), to run a subcommand in a child
// process: SystemC elaborates once per process.
std::string self_executable();

}  // namespace girtd
