// What the run measured, per stage and for the whole pipeline (the report's
// throughput keys, sim/README.md).
#include "pipeline/pipeline_elaboration.hpp"
#include "frontend/stage_costs.hpp"

namespace girtd {
namespace {

void take_fifo_series(const FifoSeries& s, StageStats& st) {
  st.fifo_in_bin_s = s.bin_s();
  st.fifo_in_series.clear();
  for (const auto& bin : s.bins()) st.fifo_in_series.push_back(bin[0]);
}

}  // namespace

void PipelineElaboration::collect(RunStats& s) const {
  const BackendResult be = time_.result();
  const double tick_s = p_.base_tick_ns * 1e-9;
  const double modeled = double(back_end_->end_tick()) * tick_s;
  s.triangles_in = back_activity_->items;
  s.triangles_drawn = be.triangles_drawn;
  s.pixels_generated = be.pixels_generated;
  s.had = be.had;
  s.dda = be.dda;
  s.sampling = be.sampling;
  s.maps = time_.screen_maps();
  s.frames = settings_.size();
  if (preparer_) s.preparer = preparer_->counts();
  if (polygon_input_) {
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
    st.fifo_in_max = in_fifo_.at(a.get())->max_occupancy;
    st.frame_begin_s = a->frame_begin_s;
    st.frame_end_s = a->frame_end_s;
    st.series_bin_s = a->series.bin_s();
    st.series = a->series.bins();
    take_fifo_series(in_fifo_.at(a.get())->occupancy, st);
    s.stages.push_back(st);
  }
  const double clock_s = p_.dda_clock_ns * 1e-9;
  StageStats dda;
  dda.name = "dda";
  dda.items = be.triangles_drawn;
  dda.busy_s = double(be.dda.cycles) * clock_s;
  dda.starved_s = back_activity_->starved_s;
  dda.blocked_s = double(be.dda_wait_ticks) * tick_s;
  dda.stall_s = *dda.starved_s + *dda.blocked_s;
  dda.fifo_in_max = in_fifo_.at(back_activity_)->max_occupancy;
  take_fifo_series(in_fifo_.at(back_activity_)->occupancy, dda);
  dda.series_bin_s = back_end_->timeline().dda().bin_s();
  dda.series = back_end_->timeline().dda().bins();
  s.stages.push_back(dda);
  StageStats had;
  had.name = "had";
  had.items = be.pixels_generated;
  had.busy_s = double(be.had_busy_ticks) * tick_s;
  had.starved_s = modeled - *had.busy_s;
  had.blocked_s = 0.0;
  had.stall_s = *had.starved_s;
  had.fifo_in_max = be.fifo_max;
  if (const auto levels = time_.fifo_levels(back_end_->end_tick())) take_fifo_series(*levels, had);
  had.series_bin_s = back_end_->timeline().had().bin_s();
  had.series = back_end_->timeline().had().bins();
  s.stages.push_back(had);

  PipelineTiming t;
  t.modeled_s = modeled;
  const auto& ends = back_end_->frame_end_ticks();
  const auto& px = back_end_->frame_end_pixels();
  if (ends.size() >= 2 && ends.back() > ends.front())
    t.sustained_pixels_per_s = double(px.back() - px.front()) / (double(ends.back() - ends.front()) * tick_s);
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
  t.frame_clear_swap_s = double(back_end_->frame_ticks()) * tick_s;
  t.preparer_triangles = preparer_ ? prepared : 0;
  if (preparer_) t.preparer_capacity_triangles_per_s = rate("preparer") / preparer_ops(p_).flops();
  s.timing = t;
}

}  // namespace girtd
