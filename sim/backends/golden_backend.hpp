// --backend golden: the bit-exact preparer and DDA through the golden HAD.
// Functional: it counts DDA clocks but models no time.
#pragma once

#include "backends/had_backend.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"
#include "thesis/ddapix.hpp"

namespace girtd {

class GoldenBackend : public HadBackend {
 public:
  explicit GoldenBackend(const Params& p)
      : HadBackend(p), preparer_(p), engine_(p), thesis_params_(p.with_thesis_formats()),
        ddapix_(thesis_params_, ThesisInside::kProgram) {}
  void begin(const FrameSource& input) override;
  void prune(const PrunePlan& plan) override {
    engine_.skip_unreachable_wraps(plan.unreachable_wraps);
    engine_.compute_spans(plan.dda_spans);
  }
  bool tap_dda(std::function<void(const DdaParams&)> tap) override {
    tap_ = std::move(tap);
    return true;
  }
  void draw(const Triangle& t) override;
  void draw(const DdaParams& d) override;
  void finish(RunStats& stats) const override;

 private:
  void traverse(const DdaParams& p);
  DdaPreparer preparer_;
  DdaEngine engine_;
  Params thesis_params_;  // the appendix program's register formats
  bool thesis_mode_ = false;
  DdaPix ddapix_;
  std::function<void(const DdaParams&)> tap_;  // --dump dda
  RunStats counts_;  // triangles, pixels, the DDA's statistics
};

// Adds one triangle's DDA statistics into a running total.
void accumulate(DdaRunStats& total, const DdaRunStats& one);

}  // namespace girtd
