#include "io/frame_source.hpp"

#include <stdexcept>

#include "common/input_error.hpp"

namespace girtd {

namespace {

uint64_t first_stage_items(const TraceFrame& f, TraceLevel level) {
  return level == TraceLevel::kPolygon ? frame_objects(f.world).size() : f.triangles.size() + f.dda.size();
}

}  // namespace

FrameSource::FrameSource(Trace trace) : path_(trace.path), level_(trace.level), warnings_(std::move(trace.warnings)) {
  for (const TraceFrame& f : trace.frames) {
    settings_.push_back(f.settings);
    items_ += first_stage_items(f, level_);
  }
  held_ = std::move(trace);
}

FrameSource::FrameSource(std::string path, TraceLevel level, std::vector<FrameSettings> settings, uint64_t items,
                         std::vector<std::string> warnings, MakeFrame make)
    : path_(std::move(path)),
      level_(level),
      settings_(std::move(settings)),
      items_(items),
      warnings_(std::move(warnings)),
      make_(std::move(make)) {}

void FrameSource::repeat(size_t n) {
  if (n <= 1) return;
  if (frames() != 1)
    throw InputError("--repeat", 0, path_ + " has " + std::to_string(frames()) +
                                        " frames: --repeat draws a one-frame input N times");
  if (next_ != 0) throw std::logic_error("--repeat after a frame was taken");
  first_ = held_ ? std::move(held_->frames.front()) : make_(0);
  held_.reset();
  settings_.resize(n, settings_.front());
  items_ *= n;
}

TraceFrame FrameSource::take(size_t i) {
  if (i != next_ || i >= frames()) throw std::logic_error("frames are taken once each, in order");
  ++next_;
  if (first_) return i + 1 == frames() ? std::move(*first_) : *first_;
  if (held_) return std::move(held_->frames[i]);
  return make_(i);
}

Trace FrameSource::all() {
  Trace t;
  t.path = path_;
  t.level = level_;
  t.warnings = warnings_;
  for (size_t i = 0; i < frames(); ++i) t.frames.push_back(take(i));
  return t;
}

}  // namespace girtd
