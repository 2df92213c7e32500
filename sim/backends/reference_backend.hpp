// --backend reference: the floating-point rasterizer through the golden HAD.
#pragma once

#include "backends/had_backend.hpp"
#include "reference/reference_rasterizer.hpp"

namespace girtd {

class ReferenceBackend : public HadBackend {
 public:
  explicit ReferenceBackend(const Params& p) : HadBackend(p), rules_{p.fill_top_left, p.edge_flags} {}
  void begin(const FrameSource& input) override;
  void draw(const Triangle& t) override;
  void draw(const DdaParams& d) override;  // refused by begin(): a DDA trace holds no float triangles
  void finish(RunStats& stats) const override;

 private:
  EdgeRules rules_;
  uint64_t triangles_in_ = 0, triangles_drawn_ = 0, pixels_ = 0;
};

}  // namespace girtd
