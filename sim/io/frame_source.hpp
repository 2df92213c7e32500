// A run's input, frame by frame. A trace read from a file is held whole (the
// file's size bounds it); a scene's frames are placed only as the run takes
// them, so an animation of any length holds a few frames at a time.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/trace.hpp"

namespace girtd {

class FrameSource {
 public:
  // Makes frame i (a scene places it now). Called once a frame, in order.
  using MakeFrame = std::function<TraceFrame(size_t)>;

  // A trace held whole.
  explicit FrameSource(Trace trace);
  // Frames made on demand: `settings` holds each frame's, `items` what the
  // first stage takes over all of them (a progress line's total).
  FrameSource(std::string path, TraceLevel level, std::vector<FrameSettings> settings, uint64_t items,
              std::vector<std::string> warnings, MakeFrame make);
  // One run's: a copy would share the scene's placer (its auto-framed camera).
  FrameSource(const FrameSource&) = delete;
  FrameSource& operator=(const FrameSource&) = delete;
  FrameSource(FrameSource&&) = default;
  FrameSource& operator=(FrameSource&&) = default;

  const std::string& path() const { return path_; }
  TraceLevel level() const { return level_; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  size_t frames() const { return settings_.size(); }
  const std::vector<FrameSettings>& settings() const { return settings_; }
  // Triangles, DDA parameter sets, or (polygon level) objects over all frames.
  uint64_t items() const { return items_; }

  // A one-frame input drawn `n` times (--repeat): each frame a copy of the
  // first. Throws InputError when the input has more than one frame.
  void repeat(size_t n);

  // Frame i, given up: each frame is taken once, in order.
  TraceFrame take(size_t i);
  // Every frame at once (tests and small inputs).
  Trace all();

 private:
  std::string path_;
  TraceLevel level_;
  std::vector<FrameSettings> settings_;
  uint64_t items_ = 0;
  std::vector<std::string> warnings_;
  std::optional<Trace> held_;
  MakeFrame make_;
  std::optional<TraceFrame> first_;  // --repeat: the frame every take copies
  size_t next_ = 0;
};

}  // namespace girtd
