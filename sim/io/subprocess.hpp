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

// This program's own path (/proc/self/exe), to run a subcommand in a child
// process: SystemC elaborates once per process.
std::string self_executable();

}  // namespace girtd
