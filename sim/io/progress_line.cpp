#include "io/progress_line.hpp"

#include <cstdio>
#include <cstdlib>

namespace girtd {

ProgressLine& ProgressLine::get() {
  static ProgressLine line;
  return line;
}

void ProgressLine::start(bool on) {
  on_ = on;
  drawn_ = false;
  step_.clear();
  run_start_ = Clock::now();
  const char* after = std::getenv("GIRTD_PROGRESS_AFTER_S");
  char* end = nullptr;
  const double s = after ? std::strtod(after, &end) : 1.0;
  after_s_ = after && end != after && s >= 0 ? s : 1.0;
}

void ProgressLine::step(const std::string& step, uint64_t done, uint64_t total, const std::string& unit,
                        const std::string& detail, const std::string& where) {
  if (!on_) return;
  const Clock::time_point now = Clock::now();
  if (step != step_) {
    step_ = step;
    step_start_ = now;
  }
  const double run_s = std::chrono::duration<double>(now - run_start_).count();
  if (run_s < after_s_ || (drawn_ && now - last_draw_ < std::chrono::milliseconds(200))) return;
  last_draw_ = now;
  const double share = total ? double(done) / double(total) : 0.0;
  const double step_s = std::chrono::duration<double>(now - step_start_).count();
  char eta[64] = "";
  if (share > 0.02 && share < 1) std::snprintf(eta, sizeof eta, ", about %.0f s left", step_s * (1 - share) / share);
  char count[96] = "";
  if (!unit.empty())
    std::snprintf(count, sizeof count, "%llu/%llu %s ", static_cast<unsigned long long>(done),
                  static_cast<unsigned long long>(total), unit.c_str());
  std::fprintf(stderr, "\r\033[K[girtd] %s%s: %s%s%.0f %%%s%s%s, %.1f s", step.c_str(), where.c_str(), count,
               unit.empty() ? "" : "(",
               100.0 * share, unit.empty() ? "" : ")", eta, detail.c_str(), run_s);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::end() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
  step_.clear();
}

}  // namespace girtd
