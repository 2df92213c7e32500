// --dump LEVEL=FILE: writes the stream crossing one stage boundary, frame by
// frame, in the trace format (replayable). The back end hands the tap what
// crossed the boundary as it crosses (nothing is computed again for it).
// Checks the request when made; the file appears only on commit().
#pragma once

#include <memory>
#include <string>

#include "common/input_error.hpp"
#include "config/params.hpp"
#include "io/trace.hpp"
#include "io/trace_writer.hpp"

namespace girtd {

struct DumpRequest {
  TraceLevel level;
  std::string path;
};

class DumpTap {
 public:
  // `input`: the render's input (polygon level for models and scenes), read from `input_path`.
  DumpTap(const DumpRequest& req, TraceLevel input, const std::string& input_path, const Params& params)
      : level_(req.level) {
    if (input == TraceLevel::kThesis)
      throw InputError(req.path, 0, "a thesis trace runs the appendix program whole: it has no stage boundary to dump");
    if (input == TraceLevel::kDda && level_ == TraceLevel::kTriangle)
      throw InputError(req.path, 0, "cannot dump triangles from a DDA-level trace (the preparer's input is gone)");
    if (level_ == TraceLevel::kPolygon && input != TraceLevel::kPolygon)
      throw InputError(req.path, 0, "cannot dump polygons: the input entered below the front end");
    writer_ = std::make_unique<TraceWriter>(req.path, level_, params, "dumped by girtd render from " + input_path);
  }
  TraceLevel level() const { return level_; }
  void begin_frame(const FrameSettings& s) { writer_->begin_frame(s); }
  template <typename Item>
  void write(const Item& item) {
    writer_->write(item);
  }
  // A whole frame of an input trace (the stream that entered at `level`).
  void frame(const TraceFrame& f) {
    begin_frame(f.settings);
    if (level_ == TraceLevel::kPolygon) write(f.world);
    for (const Triangle& t : f.triangles) write(t);
    for (const DdaParams& d : f.dda) write(d);
  }
  void commit() { writer_->commit(); }

 private:
  TraceLevel level_;
  std::unique_ptr<TraceWriter> writer_;
};

}  // namespace girtd
