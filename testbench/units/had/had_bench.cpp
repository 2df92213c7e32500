// hw/had alone (with the cache it contains) between a FIFO and a VRAM in C++
// (testbench/units/vram_model.hpp), against two models: the memory side's
// timing model (sim/had/memory_side_ticks: the FIFO's count on every tick,
// when the back end is idle, and at each frame's end the page misses, busy
// ticks and ticks waiting for the VRAM, to the tick) and the golden HAD
// (models/had: the frame in VRAM after the flush, pixel for pixel, and the
// written, blended, Z-rejected and dropped counts). Each frame: a clear,
// pixels in runs along the rows of a window, with jumps (hits, misses,
// pages that collide, pixels drawn over), opaque, blended and invisible,
// pushed in bursts and pauses, then the frame-end flush; warped ticks where
// the HAD and the VRAM promise quiet. Under the thesis' design, with
// write-behind, prefetch and dirty bits, with stolen VRAM cycles, with fast
// timings and the inverted 1 - nf, and with eight 4 x 4 cache pages.
#include <deque>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "Vhad.h"
#include "Vhad_pages8.h"
#include "config/params.hpp"
#include "had/frame_buffer.hpp"
#include "had/had.hpp"
#include "had/memory_side_ticks.hpp"
#include "unit_bench.hpp"
#include "vram_model.hpp"

namespace {

// A frame of a few thousand pixels takes well under a million ticks.
constexpr uint64_t kFrameTicksAtMost = 10'000'000;
constexpr const char* kPages8Config = GIRTD_SOURCE_DIR "/testbench/variants/pages8_4x4.json";
using girtd::Params;
using unit_bench::get_bits;
using unit_bench::Mismatches;
using unit_bench::Random;
using unit_bench::set_bits;
using unit_bench::VramModel;

struct Counts {
  uint64_t pixels = 0, frames = 0, ticks = 0;
};

// Pixels as the DDA sends them: runs along a row of a 64 x 32 window (so
// that pixels are drawn over again: Z tests that fail), now and then a jump.
class PixelSource {
 public:
  PixelSource(Random& r, int screen) : r_(r), screen_(screen) { new_window(); }
  void new_window() {  // each frame somewhere else
    ox_ = int(r_.below(uint64_t(screen_ - kWidth))), oy_ = int(r_.below(uint64_t(screen_ - kHeight)));
    jump();
  }
  girtd::Pixel next() {
    if (r_.chance(0.05)) jump();
    girtd::Pixel p;
    p.x = ox_ + x_, p.y = oy_ + y_;
    p.r = uint8_t(r_.bits(8)), p.g = uint8_t(r_.bits(8)), p.b = uint8_t(r_.bits(8));
    p.z = uint16_t(zbase_ + r_.below(4096));
    const uint64_t kind = r_.below(10);
    p.nf = kind < 4 ? girtd::kNfOne : kind < 5 ? 0 : uint16_t(1 + r_.below(girtd::kNfOne - 1));
    if (++x_ == kWidth) x_ = 0, y_ = (y_ + 1) % kHeight;
    return p;
  }

 private:
  static constexpr int kWidth = 64, kHeight = 32;
  void jump() {
    x_ = int(r_.below(kWidth)), y_ = int(r_.below(kHeight));
    zbase_ = uint32_t(r_.below(65536 - 4096));
  }
  Random& r_;
  int screen_, ox_ = 0, oy_ = 0, x_ = 0, y_ = 0;
  uint32_t zbase_ = 0;
};

// One configuration on a fresh instance of the unit (reset must set what
// matters).
template <typename Top>
Counts run(Top& top, const Params& p, int frames, int pixels_per_frame, Random& r, Mismatches& m) {
  const girtd::RtlLayout l = girtd::rtl_layout(p);
  const int screen = 1 << l.screen_bits, pixels = l.page.pixels, cw = l.vram.cell_bits;
  const uint32_t first_bg = uint32_t(r.bits(24));
  VramModel vram(p, first_bg);
  girtd::FrameBuffer fb(screen, screen, uint16_t(p.depth_clear));
  girtd::Had golden(fb, p.one_minus_nf);
  girtd::MemorySideTicks model(p);
  std::deque<girtd::Pixel> fifo;
  const size_t depth = size_t(p.fifo_dda_had_depth);
  PixelSource source(r, screen);
  Counts c;

  top.clk_i = 0;
  top.rst_ni = 0;
  top.fifo_empty_i = 1;
  top.flush_i = 0;
  top.ticks_i = 1;
  top.access_ticks_i = uint32_t(p.ticks(p.had_access_ns));
  top.blend_ticks_i = uint32_t(p.ticks(p.had_blend_extra_ns));
  top.one_minus_exact_i = p.one_minus_nf == girtd::OneMinusNf::kExact;
  top.write_behind_i = p.had_write_behind;
  top.prefetch_i = p.had_prefetch;
  top.dirty_bits_i = p.had_dirty_bits;
  top.vram_busy_i = top.vram_done_i = 0;
  top.eval();
  top.clk_i = 1;
  top.eval();
  top.rst_ni = 1;

  uint64_t t = 0;
  for (int frame = 0; frame < frames; ++frame) {
    // The frame clear (the first frame's VRAM starts cleared to first_bg).
    const uint32_t bg = frame == 0 ? first_bg : uint32_t(r.bits(24));
    bool clear = frame != 0, flush = false, flushed = false;
    fb.clear_back({uint8_t(bg >> 16), uint8_t(bg >> 8), uint8_t(bg)});
    source.new_window();
    // The middle frame: three invisible pixels, which leave slots empty and
    // pages loaded but clean.
    int left = frame == 1 ? 3 : pixels_per_frame;
    double p_push = 0.5;
    const uint64_t frame_start = t;
    for (;; ++t) {
      if (t - frame_start > kFrameTicksAtMost) {  // a hang is a failure, not a wait
        m.check(false, t,
                "frame " + std::to_string(frame) + " not done after " + std::to_string(kFrameTicksAtMost) +
                    " ticks (HAD idle " + std::to_string(top.idle_o) + ", FIFO " + std::to_string(fifo.size()) + ")");
        return c;
      }
      if (t % 61 == 0) p_push = r.chance(0.3) ? 0.05 : r.chance(0.5) ? 0.5 : 1.0;  // pauses and bursts
      model.run_until(t);
      // This tick's inputs: the FIFO's head, the VRAM's signals.
      top.clk_i = 0;
      top.fifo_empty_i = fifo.empty();
      // What the HAD must not use is noise: the FIFO's word while it is
      // empty, the VRAM's data but on a fetch's last tick.
      for (int i = 0; i < l.fifo.width; i += 32)
        set_bits(&top.fifo_data_i[0], i, std::min(32, l.fifo.width - i), r.bits(32));
      for (int i = 0; i < pixels * cw; i += 32)
        set_bits(&top.vram_rdata_i[0], i, std::min(32, pixels * cw - i), r.bits(32));
      if (!fifo.empty()) {
        const girtd::Pixel& h = fifo.front();
        uint32_t* w = &top.fifo_data_i[0];
        set_bits(w, l.fifo.x.lsb, l.fifo.x.width, uint32_t(h.x));
        set_bits(w, l.fifo.y.lsb, l.fifo.y.width, uint32_t(h.y));
        set_bits(w, l.fifo.r.lsb, l.fifo.r.width, h.r);
        set_bits(w, l.fifo.g.lsb, l.fifo.g.width, h.g);
        set_bits(w, l.fifo.b.lsb, l.fifo.b.width, h.b);
        set_bits(w, l.fifo.nf.lsb, l.fifo.nf.width, h.nf);
        set_bits(w, l.fifo.z.lsb, l.fifo.z.width, h.z);
      }
      top.vram_busy_i = vram.port().busy();
      top.vram_done_i = vram.port().done();
      if (vram.fetch_done())
        for (int i = 0; i < pixels; ++i) set_bits(&top.vram_rdata_i[0], i * cw, cw, vram.fetched()[size_t(i)]);
      top.flush_i = 0;
      top.ticks_i = 1;
      top.eval();
      // The timing model, on this tick.
      const bool vram_free = !vram.port().busy();  // can take a request (its last operation may end now)
      m.check(model.fifo_count() == fifo.size(), t,
              "FIFO count " + std::to_string(fifo.size()) + ", model " + std::to_string(model.fifo_count()));
      m.check(model.idle() == (top.idle_o && fifo.empty() && vram_free), t,
              "idle: HAD " + std::to_string(top.idle_o) + ", FIFO " + std::to_string(fifo.size()) + ", VRAM free " +
                  std::to_string(vram_free) + "; model " + std::to_string(model.idle()));
      // The frame-end flush once every pixel is drawn and the back end idle
      // (the system's contract: sim/had/memory_side_ticks.hpp); the frame is
      // in VRAM once the flush is done.
      const bool back_end_idle = top.idle_o && fifo.empty() && vram_free;
      if (flushed && back_end_idle && !vram.port().finishing() && !clear) break;
      flush = left == 0 && !flushed && back_end_idle && !clear;
      top.flush_i = flush;  // registered: read on the edge
      // The HAD's VRAM request, and the clear on the first tick of a frame.
      const bool req = top.vram_req_o, we = top.vram_we_o;
      const uint32_t page = top.vram_page_o;
      std::vector<uint64_t> cells;
      if (req && we)
        for (int i = 0; i < pixels; ++i) cells.push_back(get_bits(&top.vram_wdata_o[0], i * cw, cw));
      m.check(!(req && vram.port().busy()), t, "a VRAM request while the port is busy");
      const bool pop = top.fifo_pop_o;
      m.check(!(pop && fifo.empty()), t, "a pop from an empty FIFO");
      // The DDA's side: a pixel pushed on this tick is in the FIFO from the next.
      const bool push = left > 0 && !clear && fifo.size() + (pop ? 0 : 1) <= depth && r.chance(p_push);
      // Or the tick warp, when nothing is pushed or asked for: one edge for
      // ticks both the HAD (quiet_o) and the VRAM promise quiet.
      const girtd::VramPortTicks& port = vram.port();
      const uint64_t vram_quiet = port.quiet() || port.port_busy() || port.finishing() ? port.counting_ticks(1000) : 0;
      const uint64_t quiet = std::min<uint64_t>(top.quiet_o, vram_quiet);
      m.check(!(quiet >= 1 && (req || pop)), t, "a request or a pop on a tick the HAD promised quiet");
      if (!push && !clear && !flush && quiet >= 1 && r.chance(0.3)) {
        const uint64_t warp = 1 + r.below(quiet);
        top.ticks_i = uint32_t(warp);
        top.eval();
        top.clk_i = 1;
        top.eval();
        vram.count(warp);
        t += warp - 1;
        continue;
      }
      top.clk_i = 1;
      top.eval();
      vram.edge(req, we, page, cells, clear, bg, false);
      try {  // the model refuses what the RTL did out of turn: a disagreement, not a crash
        if (clear) model.clear();
        if (flush) model.flush();
      } catch (const std::logic_error& e) {
        m.check(false, t, e.what());
        return c;
      }
      if (pop && !fifo.empty()) fifo.pop_front();
      if (push) {
        girtd::Pixel px = source.next();
        if (frame == 1) px.nf = 0;
        fifo.push_back(px);
        model.push(l.page.number_of(px.x, px.y), golden.update(px), t);
        --left;
        ++c.pixels;
      }
      clear = false;
      flushed = flushed || flush;
      flush = false;
    }
    // The frame: every pixel's back-buffer colour and Z, as golden drew it.
    uint64_t wrong = 0;
    for (int y = 0; y < screen; ++y)
      for (int x = 0; x < screen; ++x) {
        const girtd::Rgb& rgb = fb.back_rgb(x, y);
        const uint64_t want =
            (uint64_t((uint32_t(rgb.r) << 16) | (uint32_t(rgb.g) << 8) | rgb.b) << l.vram.z.width) | fb.z(x, y);
        wrong += vram.back_cell(l.page.vram_address(x, y)) != want;
      }
    m.check(wrong == 0, t,
            "frame " + std::to_string(frame) + ": " + std::to_string(wrong) + " pixels differ from golden's");
    const girtd::HadCounts& g = golden.counts();
    m.check(top.written_o == g.written && top.blended_o == g.blended && top.z_rejected_o == g.z_rejected &&
                top.dropped_o == g.dropped,
            t, "outcome counts differ from golden's");
    m.check(top.page_misses_o == model.page_misses(), t,
            "page misses " + std::to_string(top.page_misses_o) + ", model " + std::to_string(model.page_misses()));
    m.check(top.busy_ticks_o == model.busy_ticks(), t,
            "busy ticks " + std::to_string(top.busy_ticks_o) + ", model " + std::to_string(model.busy_ticks()));
    m.check(top.vram_wait_ticks_o == model.vram_wait_ticks(), t,
            "VRAM wait ticks " + std::to_string(top.vram_wait_ticks_o) + ", model " +
                std::to_string(model.vram_wait_ticks()));
    ++c.frames;
  }
  c.ticks = t;
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  const unit_bench::Args a = unit_bench::parse_args(argc, argv);
  VerilatedContext ctx;
  unit_bench::seed(ctx, a);
  unit_bench::Instances instances;
  Random r(a.seed);
  Mismatches m("had");
  using nlohmann::json;
  const json options = {{"had", {{"write_behind", true}, {"prefetch", true}, {"dirty_bits", true}}}};
  const json fast = {{"had", {{"access_ns", 5.0}, {"blend_extra_ns", 0.0}, {"one_minus_nf", "invert_bits"}}},
                     {"vram", {{"cycle_ns", 15.0}, {"serial_ns", 5.0}, {"serial_transfers", 4}}}};
  const json steals = {{"vram", {{"steal_every_ns", 500.0}}}};
  // Pixels per run: about a tenth of the ticks asked for (a pixel takes ~10 ticks).
  const int per_frame = int(std::max<uint64_t>(200, a.ticks / 10 / 3 / 8));
  std::string summary;
  auto tell = [&](const char* name, const Counts& c) {
    summary += std::string(summary.empty() ? "" : "; ") + name + " " + std::to_string(c.frames) + " frames, " +
               std::to_string(c.pixels) + " pixels, " + std::to_string(c.ticks) + " ticks";
  };
  tell("thesis", run(instances.fresh<Vhad>(ctx, "thesis"), Params::defaults(), 3, per_frame, r, m));
  tell("options",
       run(instances.fresh<Vhad>(ctx, "options"), Params::with_overrides(options, "had bench"), 3, per_frame, r, m));
  tell("steals",
       run(instances.fresh<Vhad>(ctx, "steals"), Params::with_overrides(steals, "had bench"), 3, per_frame, r, m));
  tell("fast", run(instances.fresh<Vhad>(ctx, "fast"), Params::with_overrides(fast, "had bench"), 3, per_frame, r, m));
  json eight = json::parse(std::ifstream(kPages8Config));
  tell("pages8", run(instances.fresh<Vhad_pages8>(ctx, "pages8"), Params::with_overrides(eight, kPages8Config), 3,
                     per_frame, r, m));
  eight.merge_patch(options);
  tell("pages8+options", run(instances.fresh<Vhad_pages8>(ctx, "pages8_options"),
                             Params::with_overrides(eight, kPages8Config), 3, per_frame, r, m));
  return unit_bench::finish(ctx, a, m, "had", summary);
}
