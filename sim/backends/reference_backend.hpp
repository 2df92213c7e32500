// --backend reference: the floating-point rasterizer through the golden HAD.
#pragma once

#include "backends/backend.hpp"
#include "reference/reference_rasterizer.hpp"

namespace girtd {

class ReferenceBackend : public Backend {
 public:
  explicit ReferenceBackend(const EdgeRules& rules) : rules_(rules) {}
  std::string name() const override { return "reference"; }
  void begin(const Trace& trace) override;
  void draw_frame(const TraceFrame& frame, Had& had, RunStats& stats) override;
  void finish(RunStats& stats) const override;

 private:
  EdgeRules rules_;
};

}  // namespace girtd
