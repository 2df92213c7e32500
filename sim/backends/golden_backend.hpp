// --backend golden: the bit-exact preparer and DDA through the golden HAD.
// Functional: it counts DDA clocks but models no time.
#pragma once

#include "backends/backend.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_preparer.hpp"

namespace girtd {

class GoldenBackend : public Backend {
 public:
  explicit GoldenBackend(const Params& p) : preparer_(p), engine_(p) {}
  std::string name() const override { return "golden"; }
  std::vector<std::string> not_modeled() const override;
  void check_input(const Trace& trace) const override;
  void draw_frame(const TraceFrame& frame, Had& had, RunStats& stats) override;
  void finish(RunStats& stats) const override;

 private:
  void run_dda(const DdaParams& p, Had& had, RunStats& stats);
  DdaPreparer preparer_;
  DdaEngine engine_;
};

// Adds one triangle's DDA statistics into a running total.
void accumulate(DdaRunStats& total, const DdaRunStats& one);

}  // namespace girtd
