// A VRAM in C++ for the unit benches: its port's timing is the memory
// side's model (sim/vram/vram_port_ticks), its data two RGB buffers and Z
// per pixel. The VRAM bench holds hw/vram against it; the HAD bench uses it
// as the HAD's memory. As hw/vram: an operation is taken on a clock edge
// (a due stolen cycle first, then a clear, then a request), a fetch reads
// its page when taken (after a write or clear ending on that edge), a write
// or a clear lands when it ends, and both use the back buffer of the tick
// they were taken on.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "config/params.hpp"
#include "layout/rtl_layout.hpp"
#include "vram/vram_port_ticks.hpp"

namespace unit_bench {

class VramModel {
 public:
  // Every pixel starts as `background` with the clear depth.
  VramModel(const girtd::Params& p, uint32_t background)
      : layout_(girtd::rtl_layout(p)),
        z_clear_(uint32_t(p.depth_clear)),
        port_(p),
        rgb_{std::vector<uint32_t>(size(), background), std::vector<uint32_t>(size(), background)},
        z_(size(), z_clear_) {}

  const girtd::RtlLayout& layout() const { return layout_; }
  girtd::VramPortTicks& port() { return port_; }
  const girtd::VramPortTicks& port() const { return port_; }
  bool front() const { return front_; }
  int pixels() const { return layout_.page.pixels; }
  // A fetch ends on this tick: its page's cells ({RGB, Z}, the back buffer when it was taken).
  bool fetch_done() const { return port_.done() && op_.kind == Kind::kRead; }
  const std::vector<uint64_t>& fetched() const { return op_.cells; }
  // The back buffer's cell of a pixel address {page, index}.
  uint64_t back_cell(size_t address) const { return (uint64_t(rgb_[back()][address]) << z_bits()) | z_[address]; }

  // The clock edge. `req`: a page request (`we` a write of `cells`); `clear`:
  // the frame clear asked for on this tick, to `background`; `swap`: the
  // buffers change places after this edge.
  void edge(bool req, bool we, uint32_t page, const std::vector<uint64_t>& cells, bool clear, uint32_t background,
            bool swap) {
    const bool finishing = port_.finishing(), port_busy = port_.port_busy();
    const bool steal = !port_busy && port_.steal_due();
    const bool clear_pending = port_.claimed() && !port_.steal_due();
    if (finishing) land();
    if (steal) {
      op_ = Operation{};
    } else if (!port_busy && (clear_pending || clear)) {
      op_ = Operation{Kind::kClear, back(), 0, background, {}};
    } else if (!port_busy && req) {
      op_ = Operation{we ? Kind::kWrite : Kind::kRead, back(), page, 0, we ? cells : page_cells(page, back())};
    }
    if (swap) front_ = !front_;
    port_.edge(req, clear);
  }
  void count(uint64_t ticks) { port_.count(ticks); }  // warped ticks: only timers move

 private:
  enum class Kind { kNone, kRead, kWrite, kClear };
  struct Operation {
    Kind kind = Kind::kNone;
    int buffer = 0;
    uint32_t page = 0, background = 0;
    std::vector<uint64_t> cells;
  };

  size_t size() const { return size_t(1) << (2 * layout_.screen_bits); }
  int z_bits() const { return layout_.vram.z.width; }
  int back() const { return front_ ? 0 : 1; }  // buffer 0 is shown while the front flag is 0
  size_t address(uint32_t page, int i) const { return (size_t(page) << layout_.page.index_bits) | size_t(i); }
  std::vector<uint64_t> page_cells(uint32_t page, int buffer) const {
    std::vector<uint64_t> cells;
    for (int i = 0; i < pixels(); ++i)
      cells.push_back((uint64_t(rgb_[buffer][address(page, i)]) << z_bits()) | z_[address(page, i)]);
    return cells;
  }
  void land() {  // what the operation ending now does to the array
    if (op_.kind == Kind::kWrite) {
      for (int i = 0; i < pixels(); ++i) {
        rgb_[op_.buffer][address(op_.page, i)] = uint32_t(op_.cells[size_t(i)] >> z_bits());
        z_[address(op_.page, i)] = uint32_t(op_.cells[size_t(i)] & ((uint64_t(1) << z_bits()) - 1));
      }
    } else if (op_.kind == Kind::kClear) {
      std::fill(rgb_[op_.buffer].begin(), rgb_[op_.buffer].end(), op_.background);
      std::fill(z_.begin(), z_.end(), z_clear_);
    }
    if (op_.kind != Kind::kRead) op_ = Operation{};  // a fetch's cells stay readable until the next operation
  }

  girtd::RtlLayout layout_;
  uint32_t z_clear_;
  girtd::VramPortTicks port_;
  bool front_ = false;
  std::vector<uint32_t> rgb_[2], z_;
  Operation op_;
};

}  // namespace unit_bench
