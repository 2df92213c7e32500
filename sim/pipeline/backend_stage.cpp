#include "pipeline/backend_stage.hpp"

#include <cmath>

namespace girtd {

using sc_core::sc_time;
using sc_core::sc_time_stamp;

BackendStage::BackendStage(const sc_core::sc_module_name& name, Backend& backend,
                           const std::vector<FrameSettings>& frames, double tick_ns, double dda_clock_ns,
                           StageActivity& activity, FifoActivity& in_fifo, FrameDone frame_done, Progress progress)
    : sc_module(name), backend_(backend), time_(*backend.modeled_time()), frames_(frames), tick_ns_(tick_ns), a_(activity), in_fifo_(in_fifo),
      frame_done_(std::move(frame_done)), progress_(std::move(progress)), timeline_(tick_ns * 1e-9, dda_clock_ns * 1e-9) {
  SC_THREAD(run);
  SC_THREAD(sample);
}

sc_time BackendStage::at(uint64_t tick) const { return sc_time(static_cast<double>(tick) * tick_ns_, sc_core::SC_NS); }

uint64_t BackendStage::tick_of(const sc_time& t) const {
  return static_cast<uint64_t>(std::ceil(t.to_seconds() * 1e9 / tick_ns_ - 1e-6));
}

void BackendStage::sync_to(uint64_t tick) {
  const sc_time t = at(tick);
  if (t > sc_time_stamp()) wait(t - sc_time_stamp());
}

void BackendStage::sync_to_ns(double t_ns) {
  const sc_time t(t_ns, sc_core::SC_NS);
  if (t > sc_time_stamp()) wait(t - sc_time_stamp());
}

// A tick of the RTL inside the waveform's window: bring SystemC time to it,
// then dump both sides. The clock is low for the first 2 ns of a 5 ns tick
// (the dump before the edge) and high after it.
void BackendStage::on_tick(const BackendRtl::TickProbe& p) {
  const double edge_ns = double(p.tick) * tick_ns_;
  const double t_ns = p.rising ? edge_ns : edge_ns - std::floor(tick_ns_ / 2);
  if (lockstep_ && p.rising) sync_to_ns(edge_ns);
  if (!wave_ || !wave_->wants(t_ns)) return;
  sync_to_ns(t_ns);
  if (!p.rising && p.pixel_push) wave_->log_pixel(edge_ns, p.pixel_x, p.pixel_y);
  wave_->set_frame(static_cast<uint32_t>(frame_));
  wave_->dump(t_ns);
}

// The next token; a DDA waiting for one is starved. Inside a waveform's
// window the RTL keeps ticking (and dumping) while it waits.
Token<DdaParams> BackendStage::next_token() {
  Token<DdaParams> tok;
  if (in.nb_read(tok)) return tok;
  const sc_time t0 = sc_time_stamp();
  a_.state = StageState::kStarved;
  for (;;) {
    const double now_ns = sc_time_stamp().to_seconds() * 1e9;
    if (!wave_ || !time_.rtl() || now_ns > wave_->window_end_ns()) {
      tok = in.read();
      time_.idle_until(tick_of(sc_time_stamp()));
      break;
    }
    // Until the window opens, or inside it until the next tick: SystemC
    // time moves on whether or not a token comes, and the RTL follows it
    // (the tick hook dumps each tick).
    const sc_time until = now_ns + tick_ns_ < wave_->window_start_ns()
                              ? sc_time(wave_->window_start_ns(), sc_core::SC_NS)
                              : at(tick_of(sc_time_stamp()) + 1);
    wait(until - sc_time_stamp(), in.data_written_event());
    time_.idle_until(tick_of(sc_time_stamp()));
    if (in.nb_read(tok)) break;
  }
  a_.starved_s += (sc_time_stamp() - t0).to_seconds();
  a_.state = StageState::kBusy;
  return tok;
}

// With no RTL to clock (approx), the SystemC side is sampled once per base
// tick inside the window, until the back end is done.
void BackendStage::sample() {
  if (!wave_ || time_.rtl()) return;
  for (uint64_t tick = tick_of(sc_time(wave_->window_start_ns(), sc_core::SC_NS)); !finished_; ++tick) {
    const double t_ns = double(tick) * tick_ns_;
    if (t_ns > wave_->window_end_ns()) return;
    if (!sc_core::sc_pending_activity()) return;  // nothing else will ever happen: do not keep time going
    sync_to_ns(t_ns);
    if (finished_) return;
    wave_->set_frame(static_cast<uint32_t>(frame_));
    wave_->dump(t_ns);
  }
}

void BackendStage::run() {
  if ((wave_ || lockstep_) && time_.rtl())
    time_.rtl()->on_tick([this](const BackendRtl::TickProbe& p) { on_tick(p); });
  uint64_t triangles = 0;
  a_.state = StageState::kBusy;
  // A frame's clear, or its write-back and swap, timed apart from drawing.
  auto frame_work = [this](auto&& work) {
    time_.drain();
    const uint64_t from = time_.now_tick();
    work();
    frame_ticks_ += time_.now_tick() - from;
    if (series_) timeline_.read(time_.now_tick(), time_.counters());
  };
  for (;;) {
    const uint64_t before = time_.now_tick();  // the run's end, if the next token is the last
    sync_to(time_.ready_tick());
    const Token<DdaParams> tok = next_token();
    in_fifo_.pop(sc_time_stamp().to_seconds());
    frame_ = tok.frame;
    switch (tok.kind) {
      case TokenKind::kFrameBegin:
        frame_work([&] { backend_.begin_frame(frames_.at(tok.frame)); });
        break;
      case TokenKind::kItem:
        ++a_.items;
        backend_.draw(tok.item);
        if (series_) timeline_.read(time_.now_tick(), time_.counters());
        if (progress_ && (++triangles & 15) == 0) progress_(tok.frame, triangles, at(time_.now_tick()).to_seconds());
        break;
      case TokenKind::kFrameEnd:
        frame_work([&] { backend_.end_frame(); });
        frame_end_ticks_.push_back(time_.now_tick());
        frame_end_pixels_.push_back(time_.result().pixels_generated);
        if (frame_done_) frame_done_(tok.frame);
        break;
      case TokenKind::kEnd:
        end_tick_ = before;  // not the wait for a DDA clock that no parameter set needed
        finished_ = true;
        return;
    }
  }
}

}  // namespace girtd
