// DDApix of the thesis appendix — "exactly the algorithm of fig. 4.2" —
// on the shared DDA datapath with the program's 32-bit register formats.
// One clock per EP operation (Inc_X, Dec_X, Inc_Y, Mov_Aux_Pix, Mov_Pix_Aux);
// a pixel (ATU_DSP) leaves with the operation that follows it. No fix: rows
// can be lost, and pixels one column past Xmin can be emitted, as written.
#pragma once

#include "config/params.hpp"
#include "dda/dda_engine.hpp"
#include "dda/dda_params.hpp"

namespace girtd {

enum class ThesisInside {
  kProgram,  // PIX_INTERNO: every D >= -1 (Q = 1)
  kSharp,    // every D >= 0 (the same program with a sharp inside test, Q = 0)
};

// The NF routine: Norm of each D from its high word and top fraction byte,
// T saturated, products only when more than one factor is below 1 (8 x 8,
// high byte). Registers in the thesis formats; result 0..256.
int thesis_nf(int64_t d1, int64_t d2, int64_t d3, int64_t t);

class DdaPix {
 public:
  // `p` must carry the thesis formats (Params::with_thesis_formats()).
  DdaPix(const Params& p, ThesisInside inside) : params_(p), inside_(inside) {}
  DdaRunStats run(const DdaParams& in, const DdaEngine::PixelSink& sink) const;

 private:
  const Params& params_;
  ThesisInside inside_;
};

}  // namespace girtd
