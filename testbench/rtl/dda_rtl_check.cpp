// The DDA's check build (assertions on, X/uninitialized state randomized,
// functional coverage) against the golden model: directed traces and random
// triangles with back-pressure, for one X-randomization seed. With
// --coverage FILE it writes Verilator's coverage data and fails when a cover
// point of hw/dda/dda.sv (every state, both walk directions, all 16 rows of
// the U decoder) was never hit.
//
// With --backend the whole back end (FIFO, HAD, cache, VRAM) runs too, in
// its check build, and its frames must equal the golden HAD's.
//
//   dda_rtl_check --seed S [--random N] [--coverage FILE] [--backend] [TRACE|DIR...]
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <fstream>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "rtl/backend_rtl.hpp"
#include "rtl/dda_regression.hpp"

namespace {

// coverage.dat lines: C '<\001key\002value...>' count. User cover points
// (SystemVerilog `cover property`) have page "v_user/..."; name them by hier.
struct CoverPoint {
  std::string hier;
  long count;
};

std::vector<CoverPoint> read_user_coverage(const std::string& path) {
  std::vector<CoverPoint> points;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("C '", 0) != 0) continue;
    const size_t close = line.rfind('\'');
    const std::string keys = line.substr(3, close - 3);
    const long count = std::atol(line.c_str() + close + 1);
    std::string page, hier;
    size_t pos = 0;
    while (pos < keys.size()) {
      const size_t k0 = keys.find('\001', pos);
      if (k0 == std::string::npos) break;
      const size_t v0 = keys.find('\002', k0);
      size_t next = keys.find('\001', v0);
      if (next == std::string::npos) next = keys.size();
      const std::string key = keys.substr(k0 + 1, v0 - k0 - 1), value = keys.substr(v0 + 1, next - v0 - 1);
      if (key == "page") page = value;
      if (key == "h") hier = value;
      pos = next;
    }
    if (page.rfind("v_user", 0) == 0) points.push_back({hier, count});
  }
  return points;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace girtd;
  uint32_t seed = 1;
  int random = 0;
  std::string coverage;
  bool with_backend = false;
  std::vector<std::string> traces;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--seed" && i + 1 < argc) seed = static_cast<uint32_t>(std::atol(argv[++i]));
    else if (a == "--random" && i + 1 < argc) random = std::atoi(argv[++i]);
    else if (a == "--coverage" && i + 1 < argc) coverage = argv[++i];
    else if (a == "--backend") with_backend = true;
    else traces.push_back(a);
  }
  int passed = 0, failed = 0;
  try {
    const Params base = Params::defaults();
    std::vector<std::string> expanded;
    for (const std::string& t : traces) {
      std::vector<std::string> more = t.find(".trace") == std::string::npos && t.find(".dda") == std::string::npos
                                          ? traces_under(t)
                                          : std::vector<std::string>{t};
      expanded.insert(expanded.end(), more.begin(), more.end());
    }
    DdaRtl* last = nullptr;
    std::vector<std::unique_ptr<DdaRtl>> keep;
    for (bool pipelined : {false, true}) {
      Params p = base;
      p.xy_compare_pipelined = pipelined;
      keep.push_back(std::make_unique<DdaRtl>(p, seed));
      last = keep.back().get();
      std::unique_ptr<BackendRtl> backend;
      if (with_backend) backend = make_backend_rtl(p, seed);
      std::vector<RegressionRow> rows;
      for (const std::string& t : expanded) rows.push_back(regress_trace(t, p, *last, backend.get(), 0.3));
      if (random > 0) rows.push_back(regress_random(random, seed, p, *last, backend.get(), 0.3));
      for (const RegressionRow& r : rows) {
        std::printf("%-40s %s %8llu triangles %10llu pixels  %s\n", r.name.c_str(), pipelined ? "TTL" : "ECL",
                    (unsigned long long)r.triangles, (unsigned long long)r.pixels, r.failure.empty() ? "pass" : "FAIL");
        if (!r.failure.empty()) std::printf("    first difference: %s\n", r.failure.c_str());
        (r.failure.empty() ? passed : failed)++;
      }
    }
    if (!coverage.empty()) {
      // Both models share one Verilator context per instance; write each and merge by hier.
      std::vector<CoverPoint> total;
      for (size_t i = 0; i < keep.size(); ++i) {
        const std::string file = coverage + "." + std::to_string(i);
        keep[i]->write_coverage(file);
        for (const CoverPoint& c : read_user_coverage(file)) {
          auto it = std::find_if(total.begin(), total.end(), [&](const CoverPoint& t) { return t.hier == c.hier; });
          if (it == total.end()) total.push_back(c);
          else it->count += c.count;
        }
      }
      int unhit = 0;
      for (const CoverPoint& c : total) {
        if (c.count == 0) {
          std::printf("cover point never hit: %s\n", c.hier.c_str());
          ++unhit;
        }
      }
      std::printf("coverage: %zu cover points, %d never hit\n", total.size(), unhit);
      if (total.empty() || unhit) ++failed;
      else ++passed;
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.formatted().c_str());
    return 2;
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
