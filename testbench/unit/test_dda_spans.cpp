// The DDA's span path (models/dda/dda_span.hpp: emitting runs computed
// from their ends, for triangles that cannot wrap) against the clocked path,
// the specification, on random triangles across the sequencer's variants:
// the same pixels with the same registers and clocks, the same counts per
// state, the same clipped outputs; and through the HAD, run by run against
// pixel by pixel, the same frame and the same outcome counts.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "dda/dda_preparer.hpp"
#include "dda/dda_state_machine.hpp"
#include "had/had_sink.hpp"
#include "workloads/random_triangles.hpp"

namespace girtd {
namespace {

// The n-th variant: DDApix as written (no walk fix), an unpipelined
// compare, far edges as constants, edge flags, a longer output latency,
// a narrow colour register whose fringe values clip, and T and Z outputs
// without guard bits (cut to their low bits).
Params variant(int n) {
  Params p = Params::defaults();
  p.walk_fix = n % 6 != 1;
  p.xy_compare_pipelined = n % 6 != 2;
  p.far_edges_constant = n % 6 == 3;
  p.edge_flags = n % 6 == 4;
  p.output_latency_clocks = n % 7 == 5 ? 3 : p.output_latency_clocks;
  if (n % 6 == 5) p.ep_color.int_bits = p.ep_color.out_bits + 1;
  // Outputs without guard bits: cut to their low bits, not clipped.
  if (n % 11 == 7) p.ep_t.int_bits = p.ep_t.out_bits;
  if (n % 13 == 4) p.ep_z.int_bits = p.ep_z.out_bits;
  return p;
}

bool same_emit(const DdaEmit& a, const DdaEmit& b) {
  return a.pixel.x == b.pixel.x && a.pixel.y == b.pixel.y && a.pixel.r == b.pixel.r && a.pixel.g == b.pixel.g &&
         a.pixel.b == b.pixel.b && a.pixel.z == b.pixel.z && a.pixel.nf == b.pixel.nf && a.cycle == b.cycle &&
         a.raw == b.raw && a.covered == b.covered;
}

// A sink that takes runs and keeps every pixel it gets, as the HAD reads
// them, with the clock each leaves the DDA (a run's: one each from its first).
struct RecordingRunSink {
  static constexpr bool kTakesRuns = true;
  std::vector<RunPixel>& out;
  std::vector<uint64_t>& cycles;
  void operator()(const DdaEmit& e) const {
    out.push_back({e.pixel, e.covered});
    cycles.push_back(e.cycle);
  }
  template <typename Run>
  void run(const Run& pixels) const {
    Run r = pixels;
    for (int64_t k = 0; k < r.size(); ++k) {
      out.push_back(r.next());
      cycles.push_back(r.first_cycle() + static_cast<uint64_t>(k));
    }
  }
};

}  // namespace

TEST_CASE("the DDA's span path gives the clocked path's pixels, clocks and counts", "[dda][spans]") {
  std::mt19937 rng(20261203);
  int spanned = 0, clocked_only = 0, clipped = 0, translucent = 0, on_soft_edge = 0, at_x_limit = 0;
  for (int n = 0; n < 3000; ++n) {
    const Params p = variant(n);
    FrameSettings f;
    f.q = n % 3 == 0 ? 0 : (n % 3 == 1 ? 1 : (n % 9 == 8 ? 4 : 2));
    Triangle t = random_triangle(rng, n % 5 == 0 ? 3000 : 120);
    t.interior_edges = static_cast<uint8_t>(n % 8);
    if (n % 4 == 1)  // vertices on the lattice: edges through pixels, D = 0 exactly there
      for (Vertex& v : t.v) {
        v.x = std::round(v.x);
        v.y = std::round(v.y);
      }
    DdaPreparer prep(p);
    DdaParams d;
    if (prep.prepare(t, f, d) != PrepareResult::kReady) continue;
    DdaEngine spec(p), fast(p);
    spec.skip_unreachable_wraps(true);
    fast.skip_unreachable_wraps(true);
    fast.compute_spans(true);
    std::vector<DdaEmit> a, b;
    const DdaRunStats sa = spec.run(d, [&](const DdaEmit& e) { a.push_back(e); });
    const DdaRunStats sb = fast.run(d, [&](const DdaEmit& e) { b.push_back(e); });
    INFO("triangle " << n);
    REQUIRE(sa.span_clocks == 0);
    (sb.span_clocks > 0 ? spanned : clocked_only) += 1;
    REQUIRE(sa.cycles == sb.cycles);
    REQUIRE(sa.emitted == sb.emitted);
    REQUIRE(sa.per_state == sb.per_state);
    REQUIRE(sa.ended_at_limit == sb.ended_at_limit);
    REQUIRE(sa.numerics.triangles_affected == sb.numerics.triangles_affected);
    for (int i = 0; i < kEpCount; ++i) {
      REQUIRE(sa.numerics.ep[i].wraps == sb.numerics.ep[i].wraps);
      REQUIRE(sa.numerics.ep[i].saturations == sb.numerics.ep[i].saturations);
    }
    REQUIRE(a.size() == b.size());
    for (size_t k = 0; k < a.size(); ++k) REQUIRE(same_emit(a[k], b[k]));
    // The same pixels handed over as runs (dda_run.hpp), as the HAD reads them.
    std::vector<RunPixel> runs;
    std::vector<uint64_t> run_cycles;
    fast.run_inline(d, RecordingRunSink{runs, run_cycles});
    REQUIRE(runs.size() == a.size());
    for (size_t k = 0; k < a.size(); ++k) {
      const Pixel &x = a[k].pixel, &y = runs[k].pixel;
      REQUIRE((x.x == y.x && x.y == y.y && x.r == y.r && x.g == y.g && x.b == y.b && x.z == y.z && x.nf == y.nf));
      REQUIRE(a[k].covered == runs[k].covered);
      REQUIRE(a[k].cycle == run_cycles[k]);
      on_soft_edge += !a[k].covered && a[k].pixel.nf == kNfOne;
      at_x_limit += k > 0 && a[k].pixel.y == a[k - 1].pixel.y && (x.x == d.xmin || x.x == d.xmax);
    }
    clipped += sb.span_clocks > 0 && sb.numerics.ep[kEpR].saturations + sb.numerics.ep[kEpG].saturations > 0;
    translucent += sb.span_clocks > 0 && d.ep[kEpT].dx != 0;
  }
  CHECK(spanned > 1200);      // most triangles take the span path (1,337),
  CHECK(clocked_only > 20);   // those that may wrap do not,
  CHECK(clipped > 50);        // spans whose ends clip are counted pixel by pixel,
  CHECK(translucent > 100);   // T changes along some,
  CHECK(on_soft_edge > 100);  // inside pixels lie on a soft edge (D = 0: not covered),
  CHECK(at_x_limit > 100);    // and runs go on to the X limits
}

TEST_CASE("run by run, the HAD draws the frame it draws pixel by pixel", "[dda][spans][had]") {
  std::mt19937 rng(3122026);
  uint64_t spans = 0, drawn = 0;
  for (int frame = 0; frame < 6; ++frame) {
    const Params p = variant(frame);
    FrameBuffer fb_spec(256, 192, 0xFFFF), fb_fast(256, 192, 0xFFFF);
    fb_spec.clear_back({10, 20, 30});
    fb_fast.clear_back({10, 20, 30});
    Had had_spec(fb_spec, p.one_minus_nf), had_fast(fb_fast, p.one_minus_nf);
    // Runs that leave the screen (it is smaller than the triangles' range),
    // and the thesis program's QQ switch on some frames.
    had_spec.set_screen(200, 150);
    had_fast.set_screen(200, 150);
    had_spec.set_drop_partial(frame % 3 == 2);
    had_fast.set_drop_partial(frame % 3 == 2);
    DdaEngine spec(p), fast(p);
    fast.compute_spans(true);
    DdaPreparer prep(p);
    FrameSettings f;
    f.q = frame % 2;
    uint64_t pixels_spec = 0, pixels_fast = 0;
    for (int n = 0; n < 600; ++n) {
      Triangle t = random_triangle(rng, 120);
      for (Vertex& v : t.v) {
        v.x *= 0.25;
        v.y *= 0.2;
      }
      DdaParams d;
      if (prep.prepare(t, f, d) != PrepareResult::kReady) continue;
      d.layer = n % 4;  // for re-blends (seams)
      ++drawn;
      spec.run(d, [&](const DdaEmit& e) {
        ++pixels_spec;
        had_spec.update(e.pixel, d.layer, e.covered);
      });
      spans += fast.run_inline(d, HadSink{had_fast, pixels_fast, d.layer}).span_clocks > 0;
    }
    INFO("frame " << frame);
    REQUIRE(pixels_spec == pixels_fast);
    const HadCounts& cs = had_spec.counts();
    const HadCounts& cf = had_fast.counts();
    REQUIRE(cs.written == cf.written);
    REQUIRE(cs.blended == cf.blended);
    REQUIRE(cs.z_rejected == cf.z_rejected);
    REQUIRE(cs.dropped == cf.dropped);
    REQUIRE(cs.reblended == cf.reblended);
    CHECK(cs.dropped > 0);  // some pixels fell off the screen
    fb_spec.swap();
    fb_fast.swap();
    REQUIRE(fb_spec.shown_bytes() == fb_fast.shown_bytes());
    REQUIRE(fb_spec.z_plane() == fb_fast.z_plane());
  }
  CHECK(drawn > 2500);  // 2,746 triangles drawn,
  CHECK(spans > 900);  // 979 of them on the span path
}

}  // namespace girtd
