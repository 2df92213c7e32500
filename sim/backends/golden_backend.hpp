// --backend golden: the bit-exact preparer and DDA through the golden HAD.
// Functional: it counts DDA clocks but models no time.
#pragma once

#include "backends/backend.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"
#include "thesis/ddapix.hpp"

namespace girtd {

class GoldenBackend : public Backend {
 public:
  explicit GoldenBackend(const Params& p)
      : preparer_(p), engine_(p), thesis_params_(p.with_thesis_formats()),
        ddapix_(thesis_params_, ThesisInside::kProgram) {}
  std::string name() const override { return "golden"; }
  void begin(const Trace& trace) override;
  void draw_frame(const TraceFrame& frame, Had& had, RunStats& stats) override;
  void finish(RunStats& stats) const override;
  void prune(const PrunePlan& plan) override {
    engine_.skip_unreachable_wraps(plan.unreachable_wraps);
    engine_.compute_spans(plan.dda_spans);
  }
  bool tap_dda(std::function<void(const DdaParams&)> tap) override {
    tap_ = std::move(tap);
    return true;
  }

 private:
  void run_dda(const DdaParams& p, Had& had, RunStats& stats);
  void run_thesis(const Triangle& t, Had& had, RunStats& stats);
  DdaPreparer preparer_;
  DdaEngine engine_;
  Params thesis_params_;  // the appendix program's register formats
  bool thesis_mode_ = false;
  DdaPix ddapix_;
  std::function<void(const DdaParams&)> tap_;  // --dump dda
};

// Adds one triangle's DDA statistics into a running total.
void accumulate(DdaRunStats& total, const DdaRunStats& one);

}  // namespace girtd
