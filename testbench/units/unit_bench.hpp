// What every unit bench shares (testbench/units/README.md): its command line,
// the random stimulus, the count of disagreements with the unit's C++ model,
// and Verilator's coverage written at the end.
//   UNIT_bench [--seed S] [--ticks N] [--coverage FILE]
#pragma once

#include <verilated.h>
#include <verilated_cov.h>

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace unit_bench {

struct Args {
  uint64_t seed = 1;
  uint64_t ticks = 200000;
  std::string coverage;  // where Verilator's coverage data goes ("" = nowhere)
};

inline Args parse_args(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    const bool has_value = i + 1 < argc;
    if (s == "--seed" && has_value)
      a.seed = std::strtoull(argv[++i], nullptr, 10);
    else if (s == "--ticks" && has_value)
      a.ticks = std::strtoull(argv[++i], nullptr, 10);
    else if (s == "--coverage" && has_value)
      a.coverage = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--seed S] [--ticks N] [--coverage FILE]\n", argv[0]);
      std::exit(2);
    }
  }
  return a;
}

class Random {
 public:
  explicit Random(uint64_t seed) : gen_(seed) {}
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(gen_) < p; }
  uint64_t below(uint64_t n) { return std::uniform_int_distribution<uint64_t>(0, n - 1)(gen_); }
  uint64_t bits(int n) { return n >= 64 ? gen_() : gen_() & ((uint64_t(1) << n) - 1); }

 private:
  std::mt19937_64 gen_;
};

// Every bench's Verilator context: its random values drawn from the seed,
// and registers and memories that start random (reset must set what matters).
inline void seed(VerilatedContext& ctx, const Args& a) {
  ctx.randSeed(int(a.seed));
  ctx.randReset(2);
}

// Bits [lsb, lsb + width) of a wide Verilated port (width <= 64).
inline uint64_t get_bits(const uint32_t* words, int lsb, int width) {
  uint64_t v = 0;
  for (int b = 0; b < width; ++b) v |= uint64_t((words[(lsb + b) / 32] >> ((lsb + b) % 32)) & 1u) << b;
  return v;
}
inline void set_bits(uint32_t* words, int lsb, int width, uint64_t value) {
  for (int b = 0; b < width; ++b) {
    const int at = lsb + b;
    words[at / 32] = (words[at / 32] & ~(1u << (at % 32))) | (uint32_t((value >> b) & 1u) << (at % 32));
  }
}

// Fresh instances of a unit, one per configuration (registers and memory
// start anything: X randomization), kept until the end: Verilator's coverage
// holds pointers to each instance's counters until it is written. On the
// heap: an instance with the VRAM's memory is megabytes.
class Instances {
 public:
  template <typename Top>
  Top& fresh(VerilatedContext& ctx, const char* name) {
    auto top = std::make_shared<Top>(&ctx, name);
    owned_.push_back(top);
    return *top;
  }

 private:
  std::vector<std::shared_ptr<void>> owned_;  // each deleted as its own type
};

// Disagreements with the model: the first few printed with their tick.
class Mismatches {
 public:
  explicit Mismatches(const char* unit) : unit_(unit) {}
  void check(bool ok, uint64_t tick, const std::string& what) {
    if (ok) return;
    if (++count_ <= 10) std::fprintf(stderr, "%s bench: tick %" PRIu64 ": %s\n", unit_, tick, what.c_str());
  }
  uint64_t count() const { return count_; }

 private:
  const char* unit_;
  uint64_t count_ = 0;
};

// The RTL's own assertions ($error) stop the run through Verilator; a clean
// end writes the coverage and returns the exit status.
inline int finish(VerilatedContext& ctx, const Args& a, const Mismatches& m, const char* unit,
                  const std::string& summary) {
  if (!a.coverage.empty()) ctx.coveragep()->write(a.coverage.c_str());
  std::printf("%s bench: seed %" PRIu64 ": %s; %" PRIu64 " disagreement(s) with the model\n", unit, a.seed,
              summary.c_str(), m.count());
  return m.count() ? 1 : 0;
}

}  // namespace unit_bench
