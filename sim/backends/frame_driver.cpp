#include "backends/frame_driver.hpp"

#include <cstdio>

namespace girtd {

FrameDriver::FrameDriver(std::string backend, const Trace& input, const Params& p, const RenderOptions& opt)
    : backend_(std::move(backend)),
      frames_(input.frames.size()),
      keep_frames_(opt.keep_all_frames),
      show_progress_(opt.progress),
      t0_(std::chrono::steady_clock::now()) {
  if (opt.dump) tap_ = std::make_unique<DumpTap>(*opt.dump, input, p);
}

void FrameDriver::start() { t0_ = std::chrono::steady_clock::now(); }

double FrameDriver::wall_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
}

void FrameDriver::frame_ended(const std::function<RgbImage()>& shown) {
  if (keep_frames_) kept_.push_back(shown());
}

void FrameDriver::progress(size_t frame, uint64_t done, uint64_t total, const char* unit, const std::string& detail) {
  if (!show_progress_) return;
  const double wall = wall_s();
  if (wall < 1.0) return;
  const double share = total ? double(done) / double(total) : 0.0;
  char eta[48] = "";
  if (share > 0 && share < 1) std::snprintf(eta, sizeof eta, ", about %.0f s left", wall * (1 - share) / share);
  std::fprintf(stderr, "\r[girtd] %s: frame %zu/%zu, %llu/%llu %s (%.0f %%)%s, %.1f s wall%s ", backend_.c_str(),
               frame + 1, frames_, static_cast<unsigned long long>(done), static_cast<unsigned long long>(total), unit,
               100.0 * share, detail.c_str(), wall, eta);
  printed_ = true;
}

void FrameDriver::finish(RenderOutput& out) {
  if (printed_) std::fprintf(stderr, "\n");
  out.per_frame = std::move(kept_);
  if (tap_) tap_->commit();
}

}  // namespace girtd
