// hw/cache/pixel_cache alone against the memory side's tags
// (sim/cache/cache_tags: valid, dirty, which page) and an array of cells:
// pages loaded from "VRAM", pixels written into pages the cache holds (the
// HAD's contract), slots invalidated after their flush, under head pages
// that hit, miss and collide in one slot. Every tick: the head slot's hit,
// valid, dirty, page and cells, the pixel's cell and the flush slot's
// outputs against the model (what an invalid slot holds is not compared: it
// is never used). Two builds: the thesis' one 16 x 1 page, and eight 4 x 4
// pages (testbench/variants/pages8_4x4.json).
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "Vpixel_cache.h"
#include "Vpixel_cache_pages8.h"
#include "cache/cache_tags.hpp"
#include "config/params.hpp"
#include "layout/rtl_layout.hpp"
#include "unit_bench.hpp"

namespace {

constexpr const char* kPages8Config = GIRTD_SOURCE_DIR "/testbench/variants/pages8_4x4.json";
using girtd::Params;
using unit_bench::get_bits;
using unit_bench::Mismatches;
using unit_bench::Random;
using unit_bench::set_bits;

struct Counts {
  uint64_t loads = 0, writes = 0, hits = 0, misses = 0, invalidations = 0;
};

template <typename Top>
Counts run(Top& top, const Params& p, uint64_t ticks, Random& r, Mismatches& m) {
  const girtd::RtlLayout l = girtd::rtl_layout(p);
  const int pixels = l.page.pixels, cw = l.vram.cell_bits, slots = l.cache.pages;
  const uint32_t pages = 1u << l.page.number_bits;
  girtd::CacheTags tags(l.cache, /*dirty_bits=*/true);  // the RTL keeps dirty bits; the option is the HAD's
  std::vector<std::vector<uint64_t>> cells(static_cast<size_t>(slots),
                                           std::vector<uint64_t>(static_cast<size_t>(pixels)));
  std::vector<uint32_t> held(static_cast<size_t>(slots), 0);  // the page each valid slot holds
  // Pages that collide: several per slot, and a few far ones.
  std::vector<uint32_t> hot;
  for (int i = 0; i < 3 * slots + 2; ++i) hot.push_back(uint32_t(r.below(pages)));
  Counts c;

  top.clk_i = 0;
  top.rst_ni = 0;
  top.load_i = top.write_i = top.invalidate_i = 0;
  top.eval();
  top.clk_i = 1;
  top.eval();
  top.rst_ni = 1;
  for (uint64_t t = 0; t < ticks; ++t) {
    top.clk_i = 0;
    const uint32_t head = hot[r.below(hot.size())];
    const size_t flush_slot = size_t(r.below(uint64_t(slots)));
    // The pixel in hand: in a page the cache holds, when any.
    std::vector<size_t> valid;
    for (size_t s = 0; s < size_t(slots); ++s)
      if (tags.valid(s)) valid.push_back(s);
    const bool have_pixel = !valid.empty();
    const size_t pix_slot = have_pixel ? valid[r.below(valid.size())] : 0;
    const uint32_t pix_index = uint32_t(r.below(uint64_t(pixels)));
    top.head_page_i = head;
    top.pix_page_i = have_pixel ? held[pix_slot] : hot[0];
    top.pix_index_i = pix_index;
    top.flush_slot_i = uint32_t(flush_slot);
    top.load_i = top.write_i = top.invalidate_i = 0;
    top.eval();

    const size_t head_slot = tags.slot_of(head);
    const bool hit = tags.holds(head_slot, head);
    m.check(bool(top.head_hit_o) == hit, t, "head hit");
    m.check(bool(top.head_slot_valid_o) == tags.valid(head_slot), t, "head slot valid");
    if (tags.valid(head_slot)) {
      m.check(bool(top.head_slot_dirty_o) == tags.must_write_back(head_slot), t, "head slot dirty");
      m.check(top.head_slot_page_o == held[head_slot], t, "head slot page");
      for (int i = 0; i < pixels; ++i)
        m.check(get_bits(&top.head_slot_data_o[0], i * cw, cw) == cells[head_slot][size_t(i)], t, "head slot cell");
    }
    if (have_pixel) m.check(top.pix_cell_o == cells[pix_slot][pix_index], t, "the pixel's cell");
    m.check(bool(top.flush_valid_o) == tags.valid(flush_slot), t, "flush slot valid");
    if (tags.valid(flush_slot)) {
      m.check(bool(top.flush_dirty_o) == tags.must_write_back(flush_slot), t, "flush slot dirty");
      m.check(top.flush_page_o == held[flush_slot], t, "flush slot page");
      for (int i = 0; i < pixels; ++i)
        m.check(get_bits(&top.flush_data_o[0], i * cw, cw) == cells[flush_slot][size_t(i)], t, "flush slot cell");
    }
    c.hits += hit;
    c.misses += !hit;

    // What the HAD does on this tick: load the head's page on a miss, write
    // the pixel, or invalidate the flush slot (never two on one slot).
    const bool load = !hit && r.chance(0.3);
    const bool write = !load && have_pixel && r.chance(0.5);
    const bool invalidate =
        r.chance(0.02) && !(load && tags.slot_of(head) == flush_slot) && !(write && pix_slot == flush_slot);
    std::vector<uint64_t> data(static_cast<size_t>(pixels));
    for (auto& d : data) d = r.bits(cw);
    const uint64_t write_data = r.bits(cw);
    top.load_i = load;
    top.load_page_i = head;
    for (int i = 0; i < pixels; ++i) set_bits(&top.load_data_i[0], i * cw, cw, data[size_t(i)]);
    top.write_i = write;
    top.write_data_i = write_data;
    top.invalidate_i = invalidate;
    top.eval();
    top.clk_i = 1;
    top.eval();
    if (invalidate) tags.invalidate(flush_slot), ++c.invalidations;
    if (load) {
      tags.load(head_slot, head);
      held[head_slot] = head;
      cells[head_slot] = data;
      ++c.loads;
    } else if (write) {
      tags.write(pix_slot);
      cells[pix_slot][pix_index] = write_data;
      ++c.writes;
    }
  }
  return c;
}

std::string describe(const Counts& c) {
  return std::to_string(c.hits) + " hits, " + std::to_string(c.misses) + " misses, " + std::to_string(c.loads) +
         " loads, " + std::to_string(c.writes) + " writes";
}

}  // namespace

int main(int argc, char** argv) {
  const unit_bench::Args a = unit_bench::parse_args(argc, argv);
  VerilatedContext ctx;
  unit_bench::seed(ctx, a);
  Vpixel_cache thesis{&ctx, "thesis"};
  Vpixel_cache_pages8 pages8{&ctx, "pages8"};
  Random r(a.seed);
  Mismatches m("cache");
  const Counts ct = run(thesis, Params::defaults(), a.ticks / 2, r, m);
  // The configuration the second build's package was generated from (CMakeLists.txt).
  const Params eight = Params::with_overrides(nlohmann::json::parse(std::ifstream(kPages8Config)), kPages8Config);
  const Counts c8 = run(pages8, eight, a.ticks / 2, r, m);
  return unit_bench::finish(ctx, a, m, "cache",
                            std::to_string(a.ticks / 2) + " ticks a build; one 16 x 1 page: " + describe(ct) +
                                "; eight 4 x 4: " + describe(c8));
}
