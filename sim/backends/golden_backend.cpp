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

void GoldenBackend::begin(const FrameSource& input) {
  thesis_mode_ = input.level() == TraceLevel::kThesis;
  counts_.dda = DdaRunStats{};  // no triangle reaching the DDA: it ran 0 clocks, as rtl's counters say
  if (!thesis_mode_) return require_hardware_q(input);
  // PIX_INTERNO fixes Q = 1; the program draws a picture in the frame's top-left corner.
  had_.set_screen(thesis_params_.thesis.width, thesis_params_.thesis.height);
}

// One triangle through a sequencer (the hardware DDA, or DDApix for the
// thesis program) into the HAD.
void GoldenBackend::traverse(const DdaParams& p) {
  const HadSink sink{had_, counts_.pixels_generated, p.layer};
  const DdaRunStats one = thesis_mode_ ? ddapix_.run(p, sink) : engine_.run_inline(p, sink);
  accumulate(*counts_.dda, one);
  ++counts_.triangles_drawn;
}

void GoldenBackend::draw(const Triangle& t) {
  ++counts_.triangles_in;
  if (thesis_mode_) {  // the thesis appendix's program: prepdda and DDApix in its own formats
    if (const auto p = thesis_prepare(t.v, thesis_params_)) traverse(*p);
    return;
  }
  DdaParams p;
  if (preparer_.prepare(t, frame_, p) != PrepareResult::kReady) return;
  if (tap_) tap_(p);
  traverse(p);
}

void GoldenBackend::draw(const DdaParams& d) {
  ++counts_.triangles_in;
  if (tap_) tap_(d);
  traverse(d);
}

void GoldenBackend::finish(RunStats& stats) const {
  stats.triangles_in = counts_.triangles_in;
  stats.triangles_drawn = counts_.triangles_drawn;
  stats.pixels_generated = counts_.pixels_generated;
  stats.dda = counts_.dda;
  stats.had = had_.counts();
  stats.preparer = preparer_.counts();
  stats.stages.push_back(untimed_stage("preparer", preparer_.counts().prepared));
  stats.stages.push_back(untimed_stage("dda", counts_.triangles_drawn));
  stats.stages.push_back(untimed_stage("had", counts_.pixels_generated));
}

}  // namespace girtd
