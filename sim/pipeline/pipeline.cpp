#include "pipeline/pipeline.hpp"

#include <systemc>

#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>

#include "common/input_error.hpp"
#include "backends/backend.hpp"
#include "rtl/backend_rtl.hpp"
#include "pipeline/pipeline_elaboration.hpp"

namespace girtd {

namespace {

std::unique_ptr<Backend> make_timed(const BackendEntry& backend, const Params& p, const RenderOptions& opt) {
  if (!backend.timed()) throw std::logic_error("not a timed back end: " + backend.name);
  std::unique_ptr<Backend> made = backend.make(p, backend_request(opt));
  if (!made->modeled_time()) throw std::logic_error("a timed back end that models no time: " + backend.name);
  return made;
}

}  // namespace

PipelineElaboration::PipelineElaboration(const BackendEntry& backend, FrameSource& input, const Params& p,
                                         const RenderOptions& opt, FrameDriver& driver)
    : p_(p),
      opt_(opt),
      backend_(make_timed(backend, p, opt)),
      time_(*backend_->modeled_time()),
      driver_(driver),
      input_(input),
      settings_(input.settings()),
      polygon_input_(input.level() == TraceLevel::kPolygon) {
  DumpTap* tap = driver.tap();
  backend_->prune(opt.prune);
  backend_->begin(input);
  // The stream that entered is dumped as the source takes it (take()); one
  // made inside, by the preparer stage as it crosses (front_end_modules.cpp).
  (tap && tap->level() == input.level() ? input_tap_ : tap_) = tap;
  total_items_ = input.items();  // for the progress line
  if (polygon_input_) build_from_polygons();
  else if (input.level() == TraceLevel::kTriangle) build_from_triangles();
  else build_from_dda();
}

TraceFrame PipelineElaboration::take(size_t f) {
  return driver_.untimed([&] {  // placing a scene's frame, dumping the input: not the simulation's time
    TraceFrame frame = input_.take(f);
    if (input_tap_) input_tap_->frame(frame);
    return frame;
  });
}

RenderOutput PipelineElaboration::run() {
  if (opt_.wave) start_wave(*opt_.wave);
  driver_.start();
  sc_core::sc_start();
  const double wall = driver_.wall_s();
  if (driver_.failure()) {
    RenderOutput failed;
    failed.problem = driver_.failure();
    return failed;
  }
  if (!back_end_->finished())
    throw std::logic_error("the pipeline stopped before the back end saw the end of the run (a deadlock)");
  RenderOutput out;
  driver_.finish(out);
  collect(out.stats);
  out.shown = backend_->shown();
  out.z = backend_->z_plane();
  if (wave_) {
    WaveFiles w = wave_->finish(double(back_end_->end_tick()) * p_.base_tick_ns);
    out.wave_files = std::move(w.paths);
    out.problem = std::move(w.problem);
  }
  out.stats.wall_s = wall;  // the simulation (the frame read-out after it is not counted)
  return out;
}

void PipelineElaboration::build_back(sc_fifo<Token<DdaParams>>& in) {
  StageActivity& a = activity("back_end");
  FifoActivity& in_record = fifo_activity(in);
  in_fifo_[&a] = &in_record;
  back_activity_ = &a;
  BackendStage::FrameDone done;
  done = [this](size_t) {
    driver_.frame_ended([this] { return backend_->shown(); });
    if (driver_.failure()) sc_core::sc_stop();  // a picture could not be written: run() says so
  };
  BackendStage::Progress progress;
  if (opt_.progress)
    progress = [this](size_t frame, uint64_t triangles, double modeled_s) {
      // Polygon input: the triangle count is known only as the front end
      // makes them, so the share done is of the objects the first stage took.
      const bool polygons = polygon_input_;
      const uint64_t done = polygons ? activities_.front()->items : triangles;
      char detail[96] = "";
      if (polygons) std::snprintf(detail, sizeof detail, ", %llu triangles drawn", static_cast<unsigned long long>(triangles));
      std::snprintf(detail + std::strlen(detail), sizeof detail - std::strlen(detail), ", %.3f ms modeled", modeled_s * 1e3);
      driver_.progress(frame, done, total_items_, polygons ? "objects in" : "triangles", detail);
    };
  back_end_ = std::make_unique<BackendStage>("back_end", *backend_, settings_, p_.base_tick_ns, p_.dda_clock_ns, a, in_record,
                                             std::move(done), std::move(progress));
  back_end_->in(in);
  if (p_.pipeline_rtl_sync_every_tick && time_.rtl()) back_end_->sync_every_tick(true);
}

void PipelineElaboration::start_wave(const WaveOptions& w) {
  std::vector<std::string> stages;
  for (const auto& a : activities_) stages.push_back(a->name);
  check_pipeline_wave_scopes(w.scopes, stages);
  wave_ = std::make_unique<WaveRecorder>(w);
  for (const auto& a : activities_) wave_->add_stage(*a, in_fifo_.at(a.get()));
  if (time_.rtl()) wave_->add_rtl(*time_.rtl());  // approx: the SystemC side alone
  wave_->open();
  back_end_->record(wave_.get());
}

RenderOutput run_pipeline(const BackendEntry& backend, FrameSource& input, const Params& p, const RenderOptions& opt) {
  static bool elaborated = false;
  if (elaborated) throw std::logic_error("SystemC elaborates once per process: one pipeline run per process");
  elaborated = true;
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  if (opt.wave) {
    if (backend.has(kRunsRtl)) check_rtl_wave_scopes(opt.wave->scopes, p);  // before the run's own RTL exists
    else
      for (const std::string& s : opt.wave->scopes)
        if (s != "pipeline" && s.rfind("pipeline.", 0) != 0)
          throw InputError("--wave-scope", 0, "'" + s + "': " + backend.name + " records the SystemC side alone (pipeline...)");
  }
  FrameDriver driver(backend.name, input, p, opt);  // the dump checked before the run, committed after it
  PipelineElaboration pipeline(backend, input, p, opt, driver);
  return pipeline.run();
}

}  // namespace girtd
