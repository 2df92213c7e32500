// What every run does around its frames, whichever back end draws them:
// the render session for the untimed back ends and the SystemC back-end
// stage for the timed ones both go through it. It makes and checks the
// --dump tap before the run and commits it after; takes each frame's end
// (its picture handed on or kept for --frames all); prints the progress line with its
// ETA on a long run; and keeps the simulation's wall clock.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "backends/dump_tap.hpp"
#include "backends/render_session.hpp"
#include "common/input_error.hpp"
#include "config/params.hpp"
#include "io/png_io.hpp"
#include "io/frame_source.hpp"

namespace girtd {

class FrameDriver {
 public:
  // `input`: what enters the run (polygon level for models and scenes).
  // Throws InputError for a --dump the input cannot give.
  FrameDriver(std::string backend, const FrameSource& input, const Params& p, const RenderOptions& opt);

  DumpTap* tap() { return tap_.get(); }
  size_t frames() const { return frames_; }

  void start();  // the simulation starts: set-up before it is not timed
  // The simulation's wall time: since start(), less what ran untimed().
  double wall_s() const;
  // Runs `work` (placing the input's frame, the untimed back ends' front
  // end, writing a picture) off the simulation's clock.
  template <typename Work>
  auto untimed(Work&& work) {
    const auto t0 = std::chrono::steady_clock::now();
    struct Add {  // also when `work` throws
      FrameDriver& d;
      std::chrono::steady_clock::time_point t0;
      ~Add() { d.untimed_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
    } add{*this, t0};
    return work();
  }

  // A frame ended with its swap; `shown` is read only when frames are kept
  // or handed on (RenderOptions::on_frame). Bad output there (an InputError:
  // a picture that cannot be written) ends the run: failure() says so, and
  // no frame is handed on after it.
  void frame_ended(const std::function<RgbImage()>& shown);
  const std::optional<InputError>& failure() const { return failure_; }
  // How far the run is: `done` of `total` `unit` (polygons lit, triangles,
  // frames) in frame `frame`; `detail` follows. On the run's progress line
  // (io/progress_line.hpp).
  void progress(size_t frame, uint64_t done, uint64_t total, const char* unit, const std::string& detail = "");

  // After the run: the kept frames into `out`, the tap committed, the
  // progress line ended.
  void finish(RenderOutput& out);

 private:
  std::string backend_;
  size_t frames_, ended_ = 0;
  bool keep_frames_, show_progress_;
  FrameCallback on_frame_;
  std::unique_ptr<DumpTap> tap_;
  std::vector<RgbImage> kept_;
  std::chrono::steady_clock::time_point t0_;
  double untimed_s_ = 0;
  std::optional<InputError> failure_;
};

}  // namespace girtd
