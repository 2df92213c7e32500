// --dump LEVEL=FILE: writes the stream crossing one stage boundary, frame by
// frame, in the trace format (replayable). Checks the request when made; the
// file appears only on commit().
#pragma once

#include <memory>
#include <string>

#include "common/input_error.hpp"
#include "config/params.hpp"
#include "dda/dda_preparer.hpp"
#include "io/trace.hpp"
#include "io/trace_writer.hpp"

namespace girtd {

struct DumpRequest {
  TraceLevel level;
  std::string path;
};

class DumpTap {
 public:
  DumpTap(const DumpRequest& req, const Trace& trace, const Params& params, const Trace* polygons)
      : level_(req.level), preparer_(params), polygons_(polygons) {
    if (trace.level == TraceLevel::kThesis)
      throw InputError(req.path, 0, "a thesis trace runs the appendix program whole: it has no stage boundary to dump");
    if (trace.level == TraceLevel::kDda && level_ == TraceLevel::kTriangle)
      throw InputError(req.path, 0, "cannot dump triangles from a DDA-level trace (the preparer's input is gone)");
    if (level_ == TraceLevel::kPolygon && !polygons_)
      throw InputError(req.path, 0, "cannot dump polygons: the input entered below the front end");
    writer_ = std::make_unique<TraceWriter>(req.path, level_, params, "dumped by girtd render from " + trace.path);
  }
  void frame(const TraceFrame& f) {
    writer_->begin_frame(f.settings);
    if (level_ == TraceLevel::kPolygon) {
      writer_->write(polygons_->frames.at(polygon_frame_++).world);
      return;
    }
    if (level_ == TraceLevel::kTriangle) {
      for (const Triangle& t : f.triangles) writer_->write(t);
      return;
    }
    for (const DdaParams& d : f.dda) writer_->write(d);
    DdaParams p;
    for (const Triangle& t : f.triangles)
      if (preparer_.prepare(t, f.settings, p) == PrepareResult::kReady) writer_->write(p);
  }
  void commit() { writer_->commit(); }

 private:
  TraceLevel level_;
  DdaPreparer preparer_;
  std::unique_ptr<TraceWriter> writer_;
  const Trace* polygons_;
  size_t polygon_frame_ = 0;
};


}  // namespace girtd
