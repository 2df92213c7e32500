// How the benches that time whole renders run them: as a user does, through
// the driver (it checks the build is up to date first) when it started the
// bench, else through this executable.
#pragma once

#include <cstdlib>
#include <string>

#include "io/subprocess.hpp"

namespace girtd {

inline bool driver_started() {
  const char* driver = std::getenv("GIRTD_DRIVER");
  return driver && *driver;
}

// argv[0] of a render.
inline std::string user_render_program() { return driver_started() ? std::getenv("GIRTD_DRIVER") : self_executable(); }

// Its name in the tables.
inline const char* user_render_name() { return driver_started() ? "tools/girtd render" : "girtd render"; }

// A bar "met" needs the median 10 % past it.
inline const char* bar_verdict(double ratio, double bar) {
  return ratio <= 0.9 * bar ? "met" : ratio <= bar ? "within the bar, not 10 % past it" : "not met";
}

}  // namespace girtd
