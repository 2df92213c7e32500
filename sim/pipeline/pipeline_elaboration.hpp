// Everything one SystemC simulation of the pipeline elaborates: the FIFOs,
// the stage modules (front_end_modules.cpp), the back end, the waveform
// recorder, and what they measured (pipeline_stats.cpp). Internal to
// sim/pipeline; pipeline.hpp is the interface.
#pragma once

#include <systemc>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "backends/front_end_runner.hpp"
#include "backends/render_session.hpp"
#include "dda/dda_preparer.hpp"
#include "frontend/front_end_stages.hpp"
#include "backends/backend.hpp"
#include "backends/backend_entry.hpp"
#include "backends/frame_driver.hpp"
#include "pipeline/backend_stage.hpp"
#include "pipeline/source_stage.hpp"
#include "pipeline/timed_stage.hpp"
#include "wave/wave_recorder.hpp"

namespace girtd {

using sc_core::sc_fifo;

class PipelineElaboration {
 public:
  // `driver`: what runs around the frames (its tap: --dump's, or none).
  // `input` is taken frame by frame as the source stage reaches each.
  PipelineElaboration(const BackendEntry& backend, FrameSource& input, const Params& p, const RenderOptions& opt,
                      FrameDriver& driver);

  RenderOutput run();

 private:
  template <typename T>
  sc_fifo<Token<T>>& fifo(const std::string& name) {
    auto f = std::make_unique<sc_fifo<Token<T>>>(name.c_str(), p_.pipeline_fifo_depth);
    sc_fifo<Token<T>>& ref = *f;
    owned_.push_back(std::shared_ptr<void>(f.release(), [](void* q) { delete static_cast<sc_fifo<Token<T>>*>(q); }));
    return ref;
  }

  StageActivity& activity(const std::string& name) {
    activities_.push_back(std::make_unique<StageActivity>());
    activities_.back()->name = name;
    return *activities_.back();
  }

  double rate(const std::string& stage) const { return p_.stage_rate_flops_per_s.at(stage); }

  // A stage module between two FIFOs; `in` is read, a new FIFO is returned.
  template <typename In, typename Out>
  sc_fifo<Token<Out>>& stage(const std::string& name, sc_fifo<Token<In>>& in,
                             typename TimedStage<In, Out>::ItemFn on_item,
                             typename TimedStage<In, Out>::FrameFn on_begin = {},
                             typename TimedStage<In, Out>::FrameFn on_end = {}) {
    StageActivity& a = activity(name);
    FifoActivity& in_record = fifo_activity(in);
    in_fifo_[&a] = &in_record;
    sc_fifo<Token<Out>>& out = fifo<Out>(name + "_out");
    auto m = std::make_unique<TimedStage<In, Out>>(name.c_str(), rate(name), std::move(on_item), std::move(on_begin),
                                                   std::move(on_end), a, in_record, fifo_activity(out));
    m->in(in);
    m->out(out);
    modules_.push_back(std::move(m));
    return out;
  }

  // The push side of a FIFO is recorded on its consumer's activity: the
  // consumer is made after the producer, so keep a slot per FIFO.
  template <typename T>
  FifoActivity& fifo_activity(sc_fifo<Token<T>>& f) {
    auto& slot = fifo_records_[&f];
    if (!slot) slot = std::make_unique<FifoActivity>();
    return *slot;
  }

  template <typename T>
  sc_fifo<Token<T>>& source(typename SourceStage<T>::FrameItems items) {
    sc_fifo<Token<T>>& out = fifo<T>("source_out");
    auto m = std::make_unique<SourceStage<T>>("source", input_.frames(), std::move(items), fifo_activity(out));
    m->out(out);
    modules_.push_back(std::move(m));
    return out;
  }

  // Per-stage copies of the front end's stage functions: stages run apart
  // work on different frames at once. Their counts add up.
  FrontEndStages& front_end_instance() {
    fe_.push_back(std::make_unique<FrontEndStages>(ScreenMap{p_.screen_width, p_.screen_height}, p_.depth_max_mapped,
                                                   front_end_options(p_, opt_.prune)));
    return *fe_.back();
  }

  // The modules an input needs (front_end_modules.cpp).
  void build_from_polygons();
  void begin(FrontEndStages& s, size_t frame);  // a stage's instance starts a frame
  void build_from_triangles();
  void build_from_dda();
  // The input's frame f, taken when the source stage reaches it; the input's
  // own stream is dumped as it goes by.
  TraceFrame take(size_t f);
  sc_fifo<Token<DdaParams>>& preparer(sc_fifo<Token<Triangle>>& in);
  void build_back(sc_fifo<Token<DdaParams>>& in);

  // Per stage and whole-pipeline figures (pipeline_stats.cpp).
  void collect(RunStats& s) const;

  // Every stage's activity and its input FIFO, in pipeline order, then the
  // RTL, into one FST.
  void start_wave(const WaveOptions& w);

  const Params& p_;
  const RenderOptions& opt_;
  std::unique_ptr<Backend> backend_;
  ModeledTime& time_;  // backend_'s
  FrameDriver& driver_;  // the dump tap, kept frames, progress, wall clock
  FrameSource& input_;
  std::vector<FrameSettings> settings_;
  bool polygon_input_ = false;
  // Polygon input: a frame's world from the source stage until the last
  // front-end stage has begun it (`begun` of them so far); then each stage
  // holds it until it begins the next. So a few frames live at a time.
  struct LiveFrame {
    std::shared_ptr<const TraceFrame> frame;
    size_t begun = 0;
  };
  std::map<size_t, LiveFrame> live_frames_;
  std::map<const FrontEndStages*, std::shared_ptr<const TraceFrame>> stage_frames_;
  std::vector<std::unique_ptr<FrontEndStages>> fe_;
  std::vector<FrontPolygon> held_;
  std::vector<Triangle> to_sort_;     // the depth sort's frame, and each triangle's id
  std::vector<uint64_t> to_sort_ids_;
  std::unique_ptr<DdaPreparer> preparer_;
  std::vector<std::shared_ptr<void>> owned_;
  std::vector<std::unique_ptr<sc_core::sc_module>> modules_;
  std::unique_ptr<BackendStage> back_end_;
  std::vector<std::unique_ptr<StageActivity>> activities_;
  std::map<const StageActivity*, const FifoActivity*> in_fifo_;  // each stage's input FIFO
  std::map<const void*, std::unique_ptr<FifoActivity>> fifo_records_;
  StageActivity* back_activity_ = nullptr;
  std::unique_ptr<WaveRecorder> wave_;
  uint64_t total_items_ = 0;
  DumpTap* tap_ = nullptr;  // a stream made inside the pipeline (the preparer's input or output)
  DumpTap* input_tap_ = nullptr;  // the stream that entered, dumped as the source takes it
};

}  // namespace girtd
