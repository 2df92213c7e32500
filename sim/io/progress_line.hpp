// The one progress line a run prints on stderr (a terminal only): the step
// it is in (reading the model, the front end, the back end's frames or
// triangles), how far, and the time that step has left at its pace; shown
// once the run has taken a second (GIRTD_PROGRESS_AFTER_S=SECONDS in the
// environment sets another delay), redrawn at most 5 times a second, ended
// by a newline before anything else is printed. Process-wide, as the steps
// it follows belong to different layers of one run.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace girtd {

class ProgressLine {
 public:
  static ProgressLine& get();

  // A run that wants the line starts it (its clock with it); off by default.
  void start(bool on);
  bool on() const { return on_; }
  // `step` has done `done` of `total` `unit` since it began ("front end",
  // 4400 of 10000 "polygons"; an empty unit shows the share alone);
  // `detail` follows; `where` (", frame 2/3") is shown after the step's
  // name without starting a new step.
  void step(const std::string& step, uint64_t done, uint64_t total, const std::string& unit,
            const std::string& detail = "", const std::string& where = "");
  // The line ends (a newline) if it was drawn.
  void end();

 private:
  using Clock = std::chrono::steady_clock;
  bool on_ = false, drawn_ = false;
  double after_s_ = 1.0;
  Clock::time_point run_start_, step_start_, last_draw_;
  std::string step_;
};

}  // namespace girtd
