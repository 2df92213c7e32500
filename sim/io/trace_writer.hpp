// Writes a trace (traces/FORMAT.md) to a temporary file and moves it into
// place only on commit(), so a failed run leaves nothing half-written.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "config/params.hpp"
#include "io/trace.hpp"

namespace girtd {

class TraceWriter {
 public:
  TraceWriter(const std::string& path, TraceLevel level, const Params& params, const std::string& comment);
  ~TraceWriter();
  TraceWriter(const TraceWriter&) = delete;
  TraceWriter& operator=(const TraceWriter&) = delete;

  // Starts a frame (writes `frame` for every frame after the first) and its settings.
  void begin_frame(const FrameSettings& s);
  void write(const Triangle& t);
  void write(const DdaParams& p);
  // Level polygon: the frame's surfaces (when they changed), lights, camera,
  // focal distance, culling, then its polygons.
  void write(const WorldFrame& w);
  void commit();

 private:
  std::string path_, tmp_path_;
  std::ofstream out_;
  bool first_frame_ = true, committed_ = false;
  std::vector<Surface> written_surfaces_;
};

// The `format` record for the EP formats of `params`.
std::string dda_format_record(const Params& params);

}  // namespace girtd
