#include "dda/dda_compare.hpp"

#include <sstream>

namespace girtd {
namespace {

struct Timed {
  Pixel p;
  uint64_t cycle;
};

std::string describe(const Timed& t) {
  std::ostringstream o;
  o << "(" << t.p.x << "," << t.p.y << ") rgb " << int(t.p.r) << " " << int(t.p.g) << " " << int(t.p.b) << " z "
    << t.p.z << " nf " << t.p.nf << " at clock " << t.cycle;
  return o.str();
}

bool same(const Timed& a, const Timed& b) {
  return a.cycle == b.cycle && a.p.x == b.p.x && a.p.y == b.p.y && a.p.r == b.p.r && a.p.g == b.p.g &&
         a.p.b == b.p.b && a.p.z == b.p.z && a.p.nf == b.p.nf;
}

}  // namespace

DdaComparison compare_dda(const DdaEngine& golden, DdaRtl& rtl, const DdaParams& d, const DdaRtlOptions& opt) {
  DdaComparison c;
  std::vector<Timed> g, r;
  c.golden = golden.run(d, [&](const DdaEmit& e) { g.push_back({e.pixel, e.cycle}); });
  c.rtl = rtl.run(d, [&](const DdaEmit& e) { r.push_back({e.pixel, e.cycle}); }, opt);
  for (const Timed& t : g) c.golden_pixels.push_back(t.p);
  for (const Timed& t : r) c.rtl_pixels.push_back(t.p);
  std::ostringstream o;
  for (size_t i = 0; i < std::max(g.size(), r.size()); ++i) {
    if (i < g.size() && i < r.size() && same(g[i], r[i])) continue;
    o << "pixel " << i << ": golden " << (i < g.size() ? describe(g[i]) : "none") << ", rtl "
      << (i < r.size() ? describe(r[i]) : "none");
    c.match = false;
    break;
  }
  if (c.match && c.golden.cycles != c.rtl.stats.cycles) {
    o << "clocks: golden " << c.golden.cycles << ", rtl " << c.rtl.stats.cycles;
    c.match = false;
  }
  // The wrap detector's counts (report.json `numerics`): the same per EP.
  const EpNumerics& gn = c.golden.numerics;
  const EpNumerics& rn = c.rtl.stats.numerics;
  for (int i = 0; c.match && i < kEpCount; ++i)
    if (gn.ep[i].wraps != rn.ep[i].wraps || gn.ep[i].saturations != rn.ep[i].saturations) {
      o << kEpNames[i] << " wraps/saturations: golden " << gn.ep[i].wraps << "/" << gn.ep[i].saturations << ", rtl "
        << rn.ep[i].wraps << "/" << rn.ep[i].saturations;
      c.match = false;
    }
  if (c.match && gn.triangles_affected != rn.triangles_affected) {
    o << "triangle affected: golden " << gn.triangles_affected << ", rtl " << rn.triangles_affected;
    c.match = false;
  }
  c.first_difference = o.str();
  return c;
}

}  // namespace girtd
