#include "pipeline/pipeline.hpp"

#include <systemc>

#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>

#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"
#include "dda/dda_preparer.hpp"
#include "frontend/front_end_stages.hpp"
#include "pipeline/back_end_stage.hpp"
#include "pipeline/source_stage.hpp"
#include "pipeline/timed_stage.hpp"
#include "wave/wave_recorder.hpp"
#include "timing/stage_costs.hpp"

namespace girtd {

std::unique_ptr<BackEndEngine> make_approx_engine(const Params& p);
std::unique_ptr<BackEndEngine> make_rtl_engine(const Params& p, bool traced);

std::unique_ptr<BackEndEngine> make_back_end_engine(const std::string& backend, const Params& p, bool traced) {
  if (backend == "approx") return make_approx_engine(p);
  if (backend == "rtl") return make_rtl_engine(p, traced);
  throw std::logic_error("not a pipeline back end: " + backend);
}

bool is_pipeline_backend(const std::string& name) { return name == "approx" || name == "rtl"; }

void check_pipeline_input(const Trace& trace, const Params&) {
  if (trace.level == TraceLevel::kThesis)
    throw InputError(trace.path, 0, "a thesis-level trace runs the appendix program: use --backend golden");
  for (const TraceFrame& f : trace.frames)
    if (!is_hardware_q(f.settings.q))
      throw InputError(trace.path, f.settings.q_line,
                       "Q must be 0 or a power of two 1/16..8 for the hardware back ends (Norm is a shift)");
}

namespace {

using sc_core::sc_fifo;

// Everything one simulation elaborates, owned in one place.
class Pipeline {
 public:
  Pipeline(const std::string& backend, const Trace& trace, const Trace* polygons, const Params& p,
           const RenderOptions& opt)
      : p_(p), opt_(opt), engine_(make_back_end_engine(backend, p, opt.wave.has_value())), backend_(backend) {
    const Trace& in = polygons ? *polygons : trace;
    for (const TraceFrame& f : in.frames) settings_.push_back(f.settings);
    for (const TraceFrame& f : trace.frames) total_items_ += f.triangles.size() + f.dda.size();  // for the progress line
    if (polygons) build_from_polygons(*polygons);
    else if (trace.level == TraceLevel::kTriangle) build_from_triangles(trace);
    else build_from_dda(trace);
  }

  RenderOutput run() {
    if (opt_.wave) start_wave(*opt_.wave);
    const auto t0 = std::chrono::steady_clock::now();
    wall0_ = t0;
    sc_core::sc_start();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!back_end_->finished())
      throw std::logic_error("the pipeline stopped before the back end saw the end of the run (a deadlock)");
    if (progress_printed_) std::fprintf(stderr, "\n");
    RenderOutput out;
    out.per_frame = std::move(per_frame_);
    collect(out.stats);
    out.shown = engine_->shown();
    out.z = engine_->z_plane();
    if (wave_) out.wave_files = wave_->finish();
    out.stats.wall_s = wall;  // the simulation (the frame read-out after it is not counted)
    return out;
  }

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
    in_fifo_of_[&in] = &a;
    sc_fifo<Token<Out>>& out = fifo<Out>(name + "_out");
    auto m = std::make_unique<TimedStage<In, Out>>(name.c_str(), rate(name), std::move(on_item), std::move(on_begin),
                                                   std::move(on_end), a, fifo_activity(in), fifo_activity(out));
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
  sc_fifo<Token<T>>& source(const std::vector<std::vector<T>>& frames) {
    sc_fifo<Token<T>>& out = fifo<T>("source_out");
    auto m = std::make_unique<SourceStage<T>>("source", frames, fifo_activity(out));
    m->out(out);
    modules_.push_back(std::move(m));
    return out;
  }

  // Per-stage copies of the front end's stage functions: stages run apart
  // work on different frames at once. Their counts add up.
  FrontEndStages& front_end_instance() {
    fe_.push_back(std::make_unique<FrontEndStages>(ScreenMap{p_.screen_width, p_.screen_height}, p_.depth_max_mapped));
    return *fe_.back();
  }

  void build_from_polygons(const Trace& polygons) {
    polygon_source_ = &polygons;
    for (const TraceFrame& f : polygons.frames) {
      polygon_ids_.emplace_back();
      for (size_t i = 0; i < f.world.polygons.size(); ++i) polygon_ids_.back().push_back(i);
    }
    auto& src = source<size_t>(polygon_ids_);

    FrontEndStages& lit = front_end_instance();
    auto& lit_out = stage<size_t, FrontPolygon>(
        "lighting", src,
        [&lit](size_t, const size_t& i, Work<FrontPolygon>& w) {
          const WorldFrame& f = lit.frame();
          const size_t corners = f.polygons[i].p.size();
          w.push_back({lighting_ops(corners, f.lights.directional.size(), f.cull_back_faces).flops(), lit.light(i)});
        },
        [this, &lit](size_t frame, Work<FrontPolygon>&) { begin(lit, frame); });

    FrontEndStages& view = front_end_instance();
    auto& view_out = stage<FrontPolygon, FrontPolygon>(
        "view", lit_out,
        [&view](size_t, const FrontPolygon& p, Work<FrontPolygon>& w) {
          FrontPolygon q = p;
          view.view(q);
          w.push_back({view_ops(q.v.size()).flops(), std::move(q)});
        },
        [this, &view](size_t frame, Work<FrontPolygon>&) { begin(view, frame); });

    FrontEndStages& clip = front_end_instance();
    auto& clip_out = stage<FrontPolygon, FrontPolygon>(
        "depth_clip", view_out,
        [&clip](size_t, const FrontPolygon& p, Work<FrontPolygon>& w) {
          std::optional<FrontPolygon> kept = clip.depth_clip(p);
          size_t made = 0;
          if (kept)
            for (const CameraVertex& v : kept->v) made += v.created;
          w.push_back({depth_clip_ops(p.v.size(), made).flops(), std::move(kept)});
        },
        [this, &clip](size_t frame, Work<FrontPolygon>&) { begin(clip, frame); });

    // Projection holds the frame: Zmin and Zmax need every vertex first.
    FrontEndStages& proj = front_end_instance();
    auto& proj_out = stage<FrontPolygon, ScreenPolygon>(
        "projection", clip_out,
        [this, &proj](size_t, const FrontPolygon& p, Work<ScreenPolygon>&) {
          proj.note_depths(p);
          held_.push_back(p);
        },
        [this, &proj](size_t frame, Work<ScreenPolygon>&) {
          begin(proj, frame);
          held_.clear();
        },
        [this, &proj](size_t, Work<ScreenPolygon>& w) {
          const DepthMap depth = proj.depth_map();
          for (const FrontPolygon& p : held_) w.push_back({projection_ops(p.v.size()).flops(), proj.project(p, depth)});
          held_.clear();
        });

    FrontEndStages& tri = front_end_instance();
    auto& tri_out = stage<ScreenPolygon, SortableTriangle>(
        "triangulator", proj_out,
        [&tri](size_t, const ScreenPolygon& p, Work<SortableTriangle>& w) {
          Triangulated t = tri.triangulate(p);
          w.push_back({triangulator_ops(t.corners, t.method).flops(), std::nullopt});
          for (SortableTriangle& st : t.triangles) w.push_back({0, std::move(st)});
        },
        [this, &tri](size_t frame, Work<SortableTriangle>&) { begin(tri, frame); });

    FrontEndStages& sel = front_end_instance();
    auto& sel_out = stage<SortableTriangle, SortableTriangle>(
        "window_clip", tri_out,
        [&sel](size_t, const SortableTriangle& t, Work<SortableTriangle>& w) {
          std::optional<SortableTriangle> kept;
          if (sel.window_select(t)) kept = t;
          w.push_back({window_clip_ops().flops(), std::move(kept)});
        },
        [this, &sel](size_t frame, Work<SortableTriangle>&) { begin(sel, frame); });

    // The depth sort holds the frame too.
    FrontEndStages& sorter = front_end_instance();
    auto& sort_out = stage<SortableTriangle, Triangle>(
        "depth_sort", sel_out,
        [this](size_t, const SortableTriangle& t, Work<Triangle>&) { to_sort_.push_back(t); },
        [this, &sorter](size_t frame, Work<Triangle>&) {
          begin(sorter, frame);
          to_sort_.clear();
        },
        [this, &sorter](size_t, Work<Triangle>& w) {
          const uint64_t before = sorter.counts().depth_sort_comparisons;
          const std::vector<FrontTriangle> sorted = sorter.sort(to_sort_);
          w.push_back({depth_sort_ops(to_sort_.size(), sorter.counts().depth_sort_comparisons - before).flops(),
                       std::nullopt});
          for (const FrontTriangle& t : sorted) w.push_back({0, t.tri});
          to_sort_.clear();
        });
    build_back(preparer(sort_out));
  }

  void begin(FrontEndStages& s, size_t frame) {
    s.begin_frame(polygon_source_->frames[frame].world, settings_[frame].window);
  }

  void build_from_triangles(const Trace& trace) {
    for (const TraceFrame& f : trace.frames) triangles_.push_back(f.triangles);
    auto& src = source<Triangle>(triangles_);
    // The preparer makes the selection itself (and counts what it drops):
    // this stage only spends the thesis' clip-stage time on every triangle.
    auto& sel_out = stage<Triangle, Triangle>("window_clip", src, [](size_t, const Triangle& t, Work<Triangle>& w) {
      w.push_back({window_clip_ops().flops(), t});
    });
    build_back(preparer(sel_out));
  }

  void build_from_dda(const Trace& trace) {
    for (const TraceFrame& f : trace.frames) dda_sets_.push_back(f.dda);
    build_back(source<DdaParams>(dda_sets_));
  }

  sc_fifo<Token<DdaParams>>& preparer(sc_fifo<Token<Triangle>>& in) {
    preparer_ = std::make_unique<DdaPreparer>(p_);
    return stage<Triangle, DdaParams>("preparer", in, [this](size_t frame, const Triangle& t, Work<DdaParams>& w) {
      std::optional<DdaParams> d(std::in_place);
      if (preparer_->prepare(t, settings_[frame], *d) != PrepareResult::kReady) d.reset();
      w.push_back({preparer_ops().flops(), std::move(d)});
    });
  }

  void build_back(sc_fifo<Token<DdaParams>>& in) {
    StageActivity& a = activity("back_end");
    in_fifo_of_[&in] = &a;
    back_activity_ = &a;
    BackEndStage::FrameDone done;
    if (opt_.keep_all_frames) done = [this](size_t) { per_frame_.push_back(engine_->shown()); };
    BackEndStage::Progress progress;
    if (opt_.progress)
      progress = [this](size_t frame, uint64_t triangles, double modeled_s) {
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
        if (wall < 1.0) return;
        std::fprintf(stderr, "\r[girtd] %s: frame %zu/%zu, %llu/%llu triangles (%.0f %%), %.3f ms modeled, %.1f s wall ",
                     backend_.c_str(), frame + 1, settings_.size(), static_cast<unsigned long long>(triangles),
                     static_cast<unsigned long long>(total_items_),
                     total_items_ ? 100.0 * double(triangles) / double(total_items_) : 0.0, modeled_s * 1e3, wall);
        progress_printed_ = true;
      };
    back_end_ = std::make_unique<BackEndStage>("back_end", *engine_, settings_, p_.base_tick_ns, a, fifo_activity(in),
                                               std::move(done), std::move(progress));
    back_end_->in(in);
  }

  void collect(RunStats& s) const;

  // Every stage's activity and its input FIFO, in pipeline order, then the
  // RTL, into one FST.
  void start_wave(const WaveOptions& w) {
    if (!engine_->rtl()) throw InputError("--wave", 0, "waveforms need --backend rtl");
    wave_ = std::make_unique<WaveRecorder>(w);
    std::map<const StageActivity*, const FifoActivity*> in_fifo;
    for (const auto& [fifo, reader] : in_fifo_of_) in_fifo[reader] = fifo_records_.at(fifo).get();
    for (const auto& a : activities_) wave_->add_stage(*a, in_fifo.count(a.get()) ? in_fifo[a.get()] : nullptr);
    wave_->add_rtl(*engine_->rtl());
    wave_->open();
    back_end_->record(wave_.get());
  }

  const Params& p_;
  const RenderOptions& opt_;
  std::unique_ptr<BackEndEngine> engine_;
  std::string backend_;
  std::vector<FrameSettings> settings_;
  const Trace* polygon_source_ = nullptr;
  std::vector<std::vector<size_t>> polygon_ids_;
  std::vector<std::vector<Triangle>> triangles_;
  std::vector<std::vector<DdaParams>> dda_sets_;
  std::vector<std::unique_ptr<FrontEndStages>> fe_;
  std::vector<FrontPolygon> held_;
  std::vector<SortableTriangle> to_sort_;
  std::unique_ptr<DdaPreparer> preparer_;
  std::vector<std::shared_ptr<void>> owned_;
  std::vector<std::unique_ptr<sc_core::sc_module>> modules_;
  std::unique_ptr<BackEndStage> back_end_;
  std::vector<std::unique_ptr<StageActivity>> activities_;
  std::map<const void*, StageActivity*> in_fifo_of_;
  std::map<const void*, std::unique_ptr<FifoActivity>> fifo_records_;
  StageActivity* back_activity_ = nullptr;
  mutable uint64_t back_fifo_max_ = 0;
  std::vector<RgbImage> per_frame_;
  std::chrono::steady_clock::time_point wall0_;
  bool progress_printed_ = false;
  std::unique_ptr<WaveRecorder> wave_;
  uint64_t total_items_ = 0;
};

void Pipeline::collect(RunStats& s) const {
  const BackEndResult be = engine_->result();
  const double tick_s = p_.base_tick_ns * 1e-9;
  const double modeled = double(back_end_->end_tick()) * tick_s;
  s.triangles_in = back_activity_->items;
  s.triangles_drawn = be.triangles_drawn;
  s.pixels_generated = be.pixels_generated;
  s.had = be.had;
  s.dda = be.dda;
  s.frames = settings_.size();
  if (preparer_) s.preparer = preparer_->counts();
  if (polygon_source_) {
    FrontendCounts total;
    for (const auto& fe : fe_) total += fe->counts();
    s.frontend = total;
  }
  uint64_t prepared = 0;
  for (const auto& a : activities_) {
    if (a.get() == back_activity_) continue;
    if (a->name == "preparer") {
      s.triangles_in = a->items;
      prepared = a->emitted;
    }
    StageStats st;
    st.name = a->name;
    st.items = a->items;
    st.busy_s = a->busy_s;
    st.starved_s = a->starved_s;
    st.blocked_s = a->blocked_s;
    st.stall_s = a->starved_s + a->blocked_s;
    st.flops = a->flops;
    s.stages.push_back(st);
  }
  // FIFO occupancy: each record belongs to the stage reading that FIFO.
  for (const auto& [fifo, reader] : in_fifo_of_) {
    const auto rec = fifo_records_.find(fifo);
    if (rec == fifo_records_.end()) continue;
    for (StageStats& st : s.stages)
      if (st.name == reader->name) st.fifo_in_max = rec->second->max_occupancy;
    if (reader == back_activity_) back_fifo_max_ = rec->second->max_occupancy;
  }
  const double clock_s = p_.dda_clock_ns * 1e-9;
  StageStats dda;
  dda.name = "dda";
  dda.items = be.triangles_drawn;
  dda.busy_s = double(be.dda.cycles) * clock_s;
  dda.starved_s = back_activity_->starved_s;
  dda.blocked_s = double(be.dda_wait_ticks) * tick_s;
  dda.stall_s = *dda.starved_s + *dda.blocked_s;
  dda.fifo_in_max = back_fifo_max_;
  s.stages.push_back(dda);
  StageStats had;
  had.name = "had";
  had.items = be.pixels_generated;
  had.busy_s = double(be.had_busy_ticks) * tick_s;
  had.starved_s = modeled - *had.busy_s;
  had.blocked_s = 0.0;
  had.stall_s = *had.starved_s;
  had.fifo_in_max = be.fifo_max;
  s.stages.push_back(had);

  PipelineTiming t;
  t.modeled_s = modeled;
  double most = -1;
  for (const StageStats& st : s.stages)
    if (st.busy_s && *st.busy_s > most) {
      most = *st.busy_s;
      t.bottleneck = st.name;
    }
  t.cache_accesses = be.pixels_generated;
  t.page_misses = be.page_misses;
  t.dda_busy_s = *dda.busy_s;
  t.dda_fifo_full_s = *dda.blocked_s;
  t.dda_starved_s = *dda.starved_s;
  t.had_page_wait_s = double(be.had_vram_wait_ticks) * tick_s;
  t.preparer_triangles = preparer_ ? prepared : 0;
  if (preparer_) t.preparer_capacity_triangles_per_s = rate("preparer") / preparer_ops().flops();
  s.timing = t;
}

}  // namespace

RenderOutput run_pipeline(const std::string& backend, const Trace& trace, const Trace* polygons, const Params& p,
                          const RenderOptions& opt) {
  static bool elaborated = false;
  if (elaborated) throw std::logic_error("SystemC elaborates once per process: one pipeline run per process");
  elaborated = true;
  check_pipeline_input(polygons ? *polygons : trace, p);
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  std::unique_ptr<DumpTap> tap;  // checked before the run, written after it
  if (opt.dump) tap = std::make_unique<DumpTap>(*opt.dump, trace, p, opt.polygon_source);
  Pipeline pipeline(backend, trace, polygons, p, opt);
  RenderOutput out = pipeline.run();
  if (tap) {
    for (const TraceFrame& f : trace.frames) tap->frame(f);
    tap->commit();
  }
  return out;
}

}  // namespace girtd
