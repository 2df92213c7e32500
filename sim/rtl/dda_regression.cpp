#include "rtl/dda_regression.hpp"

#include <algorithm>
#include <filesystem>
#include <random>

#include "common/input_error.hpp"
#include "backends/backend.hpp"
#include "dda/dda_preparer.hpp"
#include "had/had.hpp"
#include "io/trace_reader.hpp"
#include "rtl/backend_rtl.hpp"
#include "dda/dda_compare.hpp"
#include "workloads/random_triangles.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

// Runs golden and RTL side by side over one frame's parameter sets.
class FrameChecker {
 public:
  FrameChecker(const Params& p, DdaRtl& rtl, BackendRtl* backend, double stall, uint32_t seed)
      : golden_(p), rtl_(rtl), backend_(backend), stall_(stall), seed_(seed),
        fb_golden_(p.screen_width, p.screen_height, uint16_t(p.depth_clear)),
        fb_rtl_(p.screen_width, p.screen_height, uint16_t(p.depth_clear)),
        had_golden_(fb_golden_, p.one_minus_nf), had_rtl_(fb_rtl_, p.one_minus_nf) {
    if (backend_) start_ = backend_->result();
  }

  void begin_frame(Rgb background) {
    fb_golden_.clear_back(background);
    fb_rtl_.clear_back(background);
    if (backend_) backend_->begin_frame(background);
  }

  void check(const DdaParams& d, RegressionRow& row) {
    if (!row.failure.empty()) return;
    DdaRtlOptions opt;
    opt.seed = seed_ + uint32_t(row.triangles);
    opt.stall_probability = (row.triangles % 2) ? stall_ : 0.0;  // back-pressure on every other triangle
    const DdaComparison c = compare_dda(golden_, rtl_, d, opt);
    ++row.triangles;
    row.pixels += c.golden.emitted;
    row.clocks += c.golden.cycles;
    row.stalls += c.rtl.stall_cycles;
    if (!c.match) {
      row.failure = "triangle " + std::to_string(row.triangles - 1) +
                    (d.source_line ? " (line " + std::to_string(d.source_line) + ")" : "") + ": " +
                    c.first_difference;
      return;
    }
    for (const Pixel& p : c.golden_pixels) had_golden_.update(p);
    for (const Pixel& p : c.rtl_pixels) had_rtl_.update(p);
    if (backend_) backend_->draw(d);
  }

  void end_frame(RegressionRow& row) {
    if (!row.failure.empty()) return;
    fb_golden_.swap();  // show what was just drawn
    fb_rtl_.swap();
    if (fb_golden_.shown_bytes() != fb_rtl_.shown_bytes() || fb_golden_.z_plane() != fb_rtl_.z_plane())
      row.failure = "frame buffers differ";
    if (backend_ && row.failure.empty()) check_backend(row);
  }

  // The RTL back end (DDA + FIFO + HAD + cache + VRAM) against the golden HAD:
  // the frame bit for bit, and every pixel accounted for.
  void check_backend(RegressionRow& row) {
    backend_->end_frame();
    const BackendResult now = backend_->result();
    const HadCounts& g = had_golden_.counts();
    const uint64_t generated = now.pixels_generated - start_.pixels_generated;
    const uint64_t accounted = now.had.total() - start_.had.total();
    row.ticks = now.ticks - start_.ticks;
    if (accounted != generated) {
      row.failure = "back end: generated " + std::to_string(generated) + " != written + blended + rejected + dropped " +
                    std::to_string(accounted);
    } else if (now.had.written - start_.had.written != g.written || now.had.blended - start_.had.blended != g.blended ||
               now.had.z_rejected - start_.had.z_rejected != g.z_rejected ||
               now.had.dropped - start_.had.dropped != g.dropped) {
      row.failure = "back end: HAD counts differ from the golden HAD's";
    } else if (backend_->shown().rgb != fb_golden_.shown_bytes()) {
      row.failure = "back end: shown frame differs from the golden HAD's";
    } else if (backend_->z_plane() != fb_golden_.z_plane()) {
      row.failure = "back end: Z buffer differs from the golden HAD's";
    }
  }

 private:
  DdaEngine golden_;
  DdaRtl& rtl_;
  BackendRtl* backend_;
  BackendResult start_;
  double stall_;
  uint32_t seed_;
  FrameBuffer fb_golden_, fb_rtl_;
  Had had_golden_, had_rtl_;
};

}  // namespace

std::vector<std::string> traces_under(const std::string& dir) {
  std::vector<std::string> out;
  if (!fs::is_directory(dir)) throw InputError(dir, 0, "no such directory: run from the repository root or name traces");
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && (e.path().extension() == ".trace" || e.path().extension() == ".dda")) {
      // The RTL takes what reaches the preparer or the DDA: triangle and DDA levels.
      const auto level = header_level(e.path().string());
      if (level == TraceLevel::kTriangle || level == TraceLevel::kDda) out.push_back(e.path().string());
    }
  std::sort(out.begin(), out.end());
  return out;
}

RegressionRow regress_trace(const std::string& path, const Params& p, DdaRtl& rtl, BackendRtl* backend,
                            double stall) {
  RegressionRow row;
  row.name = path;
  FrameSource input(read_trace(path, std::nullopt, p));
  if (input.level() != TraceLevel::kTriangle && input.level() != TraceLevel::kDda)
    throw InputError(path, 0, std::string("regress takes triangle- and DDA-level traces, not ") + level_name(input.level()));
  require_hardware_q(input);
  FrameChecker checker(p, rtl, backend, stall, 1);
  DdaPreparer prep(p);
  for (size_t i = 0; i < input.frames(); ++i) {
    const TraceFrame f = input.take(i);
    checker.begin_frame(f.settings.background);
    DdaParams d;
    for (const Triangle& t : f.triangles)
      if (prep.prepare(t, f.settings, d) == PrepareResult::kReady) checker.check(d, row);
    for (const DdaParams& dd : f.dda) checker.check(dd, row);
    checker.end_frame(row);
  }
  return row;
}

RegressionRow regress_random(int count, uint32_t seed, const Params& p, DdaRtl& rtl, BackendRtl* backend,
                             double stall) {
  RegressionRow row;
  row.name = "random " + std::to_string(count) + " (seed " + std::to_string(seed) + ")";
  std::mt19937 rng(seed);
  const double qs[5] = {0, 0.5, 1, 1, 2};
  FrameChecker checker(p, rtl, backend, stall, seed);
  DdaPreparer prep(p);
  checker.begin_frame(Rgb{});
  for (int n = 0; n < count && row.failure.empty(); ++n) {
    FrameSettings f;
    f.q = qs[rng() % 5];
    // Mostly small and medium triangles, as scenes have; the log-uniform size reaches the full screen.
    const Triangle t = random_triangle(rng, n % 10 == 0 ? 1024 : 64);
    DdaParams d;
    if (prep.prepare(t, f, d) == PrepareResult::kReady) checker.check(d, row);
  }
  checker.end_frame(row);
  return row;
}


}  // namespace girtd
