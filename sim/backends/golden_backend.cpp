#include "backends/golden_backend.hpp"

#include "common/input_error.hpp"
#include "dda/dda_state_machine.hpp"
#include "had/had_sink.hpp"
#include "thesis/thesis_preparer.hpp"

namespace girtd {

void accumulate(DdaRunStats& total, const DdaRunStats& one) {
  total.numerics.add_triangle(one.numerics, total.triangles);
  total.triangles += one.triangles;
  total.cycles += one.cycles;
  total.emitted += one.emitted;
  for (size_t i = 0; i < total.per_state.size(); ++i) total.per_state[i] += one.per_state[i];
  total.ended_at_limit = total.ended_at_limit || one.ended_at_limit;
  total.undetected += one.undetected;
  total.span_clocks += one.span_clocks;
}

void GoldenBackend::begin(const Trace& trace) {
  thesis_mode_ = trace.level == TraceLevel::kThesis;
  if (trace.level == TraceLevel::kThesis) return;  // PIX_INTERNO fixes Q = 1
  require_hardware_q(trace);
}

namespace {

DdaRunStats run_sequencer(const DdaPix& seq, const DdaParams& p, const HadSink& sink) { return seq.run(p, sink); }
DdaRunStats run_sequencer(const DdaEngine& seq, const DdaParams& p, const HadSink& sink) {
  return seq.run_inline(p, sink);
}

// One triangle through a sequencer (the hardware DDA or DDApix) into the HAD.
template <typename Sequencer>
void traverse(const Sequencer& seq, const DdaParams& p, Had& had, RunStats& stats) {
  const DdaRunStats one = run_sequencer(seq, p, HadSink{had, stats.pixels_generated, p.layer});
  if (!stats.dda) stats.dda = DdaRunStats{};
  accumulate(*stats.dda, one);
  ++stats.triangles_drawn;
}

}  // namespace

void GoldenBackend::run_dda(const DdaParams& p, Had& had, RunStats& stats) {
  if (tap_) tap_(p);
  traverse(engine_, p, had, stats);
}

// The thesis appendix's program: prepdda and DDApix in its own formats.
void GoldenBackend::run_thesis(const Triangle& t, Had& had, RunStats& stats) {
  ++stats.triangles_in;
  const auto p = thesis_prepare(t.v, thesis_params_);
  if (p) traverse(ddapix_, *p, had, stats);
}

void GoldenBackend::draw_frame(const TraceFrame& frame, Had& had, RunStats& stats) {
  if (thesis_mode_) {
    for (const Triangle& t : frame.triangles) run_thesis(t, had, stats);
    return;
  }
  DdaParams p;
  for (const Triangle& t : frame.triangles) {
    ++stats.triangles_in;
    if (preparer_.prepare(t, frame.settings, p) == PrepareResult::kReady) run_dda(p, had, stats);
  }
  for (const DdaParams& d : frame.dda) {
    ++stats.triangles_in;
    run_dda(d, had, stats);
  }
}

void GoldenBackend::finish(RunStats& stats) const {
  if (!stats.dda) stats.dda = DdaRunStats{};  // no triangle reached the DDA: it ran 0 clocks, as rtl's counters say
  stats.preparer = preparer_.counts();
  stats.stages.push_back(untimed_stage("preparer", preparer_.counts().prepared));
  stats.stages.push_back(untimed_stage("dda", stats.triangles_drawn));
  stats.stages.push_back(untimed_stage("had", stats.pixels_generated));
}

}  // namespace girtd
