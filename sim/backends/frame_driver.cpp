#include "backends/frame_driver.hpp"

#include <cstdio>

#include "io/progress_line.hpp"

namespace girtd {

FrameDriver::FrameDriver(std::string backend, const FrameSource& input, const Params& p, const RenderOptions& opt)
    : backend_(std::move(backend)),
      frames_(input.frames()),
      keep_frames_(opt.keep_all_frames),
      show_progress_(opt.progress),
      on_frame_(opt.on_frame),
      t0_(std::chrono::steady_clock::now()) {
  if (opt.dump) tap_ = std::make_unique<DumpTap>(*opt.dump, input.level(), input.path(), p);
}

void FrameDriver::start() {
  t0_ = std::chrono::steady_clock::now();
  untimed_s_ = 0;
}

double FrameDriver::wall_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count() - untimed_s_;
}

void FrameDriver::frame_ended(const std::function<RgbImage()>& shown) {
  const size_t frame = ended_++;
  if (!keep_frames_ && !on_frame_) return;
  RgbImage picture = shown();
  if (on_frame_) try {
      untimed([&] { on_frame_(frame, picture); });
    } catch (const InputError& e) {
      failure_ = e;
      on_frame_ = nullptr;
    }
  if (keep_frames_) kept_.push_back(std::move(picture));
}

void FrameDriver::progress(size_t frame, uint64_t done, uint64_t total, const char* unit, const std::string& detail) {
  if (!show_progress_) return;
  const std::string where =
      frames_ > 1 && std::string(unit) != "frames" ? ", frame " + std::to_string(frame + 1) + "/" + std::to_string(frames_) : "";
  ProgressLine::get().step(backend_, done, total, unit, detail, where);
}

void FrameDriver::finish(RenderOutput& out) {
  ProgressLine::get().end();
  out.per_frame = std::move(kept_);
  if (tap_) tap_->commit();
}

}  // namespace girtd
