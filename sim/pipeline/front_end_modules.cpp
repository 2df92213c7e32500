// The pipeline's stage modules, by what the input is: polygons go through
// the whole front end, triangles start at the window clip, DDA parameter
// sets go straight to the back end. Each stage calls its models/ function
// and charges its flops (sim/frontend/stage_costs).
#include <stdexcept>

#include "backends/front_end_runner.hpp"
#include "common/triangle_setup.hpp"
#include "config/built_stages.hpp"
#include "pipeline/pipeline_elaboration.hpp"
#include "frontend/stage_costs.hpp"

namespace girtd {

void PipelineElaboration::build_from_polygons() {
  count_front_end_pass();
  auto& src = source<WorldObject>([this](size_t f) {
    auto frame = std::make_shared<const TraceFrame>(take(f));
    std::vector<WorldObject> objects = frame_objects(frame->world);
    live_frames_[f] = {std::move(frame), 0};
    return objects;
  });

  // Culling, in front of lighting: an object's bounding sphere (when
  // culling.objects is on), then each polygon's back-face test (when the
  // frame or culling.back_faces asks for it). Where the config builds no
  // culling stage (models/config/built_stages.hpp) this one takes no time and
  // passes every polygon on: the lighting board tests the back faces an
  // input asks to cull.
  const bool culling_built = culling_stage_built(p_);
  FrontEndStages& cull = front_end_instance();
  auto& cull_out = stage<WorldObject, size_t>(
      "culling", src,
      [&cull, culling_built](size_t, const WorldObject& o, Work<size_t>& w) {
        w.push_back({cull.options().cull_objects ? object_culling_ops().flops() : 0, std::nullopt});
        if (!cull.keep_object(o)) return;
        const WorldFrame& f = cull.frame();
        for (size_t i = o.first; i < o.first + o.count; ++i) {
          if (!culling_built) {
            w.push_back({0, i});
            continue;
          }
          const double test = cull.back_face_test_on() ? back_face_ops(f.polygons[i].p.size()).flops() : 0;
          std::optional<size_t> kept;
          if (cull.keep_polygon(i)) kept = i;
          w.push_back({test, kept});
        }
      },
      [this, &cull](size_t frame, Work<size_t>&) { begin(cull, frame); });

  FrontEndStages& lit = front_end_instance();
  auto& lit_out = stage<size_t, FrontPolygon>(
      "lighting", cull_out,
      [&lit, culling_built](size_t, const size_t& i, Work<FrontPolygon>& w) {
        const WorldFrame& f = lit.frame();
        const size_t corners = f.polygons[i].p.size();
        if (!culling_built && lit.back_face_test_on()) {
          w.push_back({back_face_ops(corners).flops(), std::nullopt});
          if (!lit.keep_polygon(i)) return;
        }
        w.push_back({lighting_ops(corners, f.lights.directional.size()).flops(), lit.light(i)});
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
        w.reserve(w.size() + held_.size());
        for (const FrontPolygon& p : held_) w.push_back({projection_ops(p.v.size()).flops(), proj.project(p, depth)});
        std::vector<FrontPolygon>().swap(held_);
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
      [this](size_t, const SortableTriangle& t, Work<Triangle>&) {
        to_sort_.push_back(t.ft.tri);
        to_sort_ids_.push_back(t.id);
      },
      [this, &sorter](size_t frame, Work<Triangle>&) {
        begin(sorter, frame);
        to_sort_.clear();
        to_sort_ids_.clear();
      },
      [this, &sorter](size_t, Work<Triangle>& w) {
        const uint64_t before = sorter.counts().depth_sort_comparisons;
        sorter.sort(to_sort_, to_sort_ids_);  // in place
        w.reserve(w.size() + 1 + to_sort_.size());
        w.push_back({depth_sort_ops(to_sort_.size(), sorter.counts().depth_sort_comparisons - before).flops(),
                     std::nullopt});
        for (const Triangle& t : to_sort_) w.push_back({0, t});
        std::vector<Triangle>().swap(to_sort_);
        std::vector<uint64_t>().swap(to_sort_ids_);
      });
  build_back(preparer(sort_out));
}

void PipelineElaboration::begin(FrontEndStages& s, size_t frame) {
  auto live = live_frames_.find(frame);  // the source stage made it before any stage begins it
  if (live == live_frames_.end()) throw std::logic_error("a front-end stage began a frame no longer (or not yet) held");
  std::shared_ptr<const TraceFrame>& held = stage_frames_[&s];
  held = live->second.frame;  // the stage's previous frame goes, unless another stage still holds it
  if (++live->second.begun == fe_.size()) live_frames_.erase(live);
  s.begin_frame(held->world, settings_[frame].window, settings_[frame].q);
}

void PipelineElaboration::build_from_triangles() {
  auto& src = source<Triangle>([this](size_t f) { return take(f).triangles; });
  // The preparer makes the selection itself (and counts what it drops):
  // this stage only spends the thesis' clip-stage time on every triangle.
  auto& sel_out = stage<Triangle, Triangle>("window_clip", src, [](size_t, const Triangle& t, Work<Triangle>& w) {
    w.push_back({window_clip_ops().flops(), t});
  });
  build_back(preparer(sel_out));
}

void PipelineElaboration::build_from_dda() {
  build_back(source<DdaParams>([this](size_t f) { return take(f).dda; }));
}

sc_core::sc_fifo<Token<DdaParams>>& PipelineElaboration::preparer(sc_fifo<Token<Triangle>>& in) {
  preparer_ = std::make_unique<DdaPreparer>(p_);
  return stage<Triangle, DdaParams>(
      "preparer", in,
      [this](size_t frame, const Triangle& t, Work<DdaParams>& w) {
        std::optional<DdaParams> d(std::in_place);
        const uint64_t limited_before = preparer_->counts().limited_planes;
        if (preparer_->prepare(t, settings_[frame], *d) != PrepareResult::kReady) d.reset();
        const double cuts = double(preparer_->counts().limited_planes - limited_before) * steep_limit_ops().flops();
        if (tap_ && tap_->level() == TraceLevel::kTriangle) tap_->write(t);
        if (tap_ && tap_->level() == TraceLevel::kDda && d) tap_->write(*d);
        w.push_back({preparer_ops(p_).flops() + cuts, std::move(d)});
      },
      [this](size_t frame, Work<DdaParams>&) {
        if (tap_) tap_->begin_frame(settings_[frame]);
      });
}

}  // namespace girtd
