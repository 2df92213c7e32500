// hw/cache's tags, without its data: per slot a valid bit, a dirty bit and
// the page it holds; direct-mapped (models/cache/cache_geometry.hpp). The
// memory side's model (sim/had/memory_side_ticks.hpp) asks and sets them
// on the ticks hw/had does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cache/cache_geometry.hpp"

namespace girtd {

class CacheTags {
 public:
  // `dirty_bits`: the cache.dirty_bits option; without it every valid page
  // is written back, written to or not.
  CacheTags(const CacheGeometry& geometry, bool dirty_bits)
      : geometry_(geometry),
        dirty_bits_(dirty_bits),
        valid_(size_t(geometry.pages), 0),
        dirty_(size_t(geometry.pages), 0),
        page_(size_t(geometry.pages), 0) {}

  size_t slots() const { return valid_.size(); }
  size_t slot_of(uint32_t page) const { return size_t(geometry_.slot_of(page)); }
  bool valid(size_t slot) const { return valid_[slot]; }
  bool holds(size_t slot, uint32_t page) const { return valid_[slot] && page_[slot] == page; }
  // The slot's page goes back to the VRAM before it is replaced or flushed.
  bool must_write_back(size_t slot) const { return valid_[slot] && (dirty_[slot] || !dirty_bits_); }

  void load(size_t slot, uint32_t page) {  // a fetched page, not yet written to
    valid_[slot] = 1;
    page_[slot] = page;
    dirty_[slot] = 0;
  }
  void write(size_t slot) { dirty_[slot] = 1; }
  void invalidate(size_t slot) { valid_[slot] = 0; }

 private:
  const CacheGeometry geometry_;
  const bool dirty_bits_;
  std::vector<uint8_t> valid_, dirty_;  // bytes, not std::vector<bool>'s bits: read on every pixel
  std::vector<uint32_t> page_;
};

}  // namespace girtd
