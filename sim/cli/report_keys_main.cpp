// girtd_report_keys: prints the key table of report.json from the key
// registry (report/report_keys.hpp) and the back-end registry
// (engine/backend_registry.hpp), the generated section of sim/README.md;
// with --backends, the back ends' capability table of docs/architecture.md
// (tools/generated_docs.py writes both there and checks they are current).
#include <cstdio>
#include <cstring>
#include <string>

#include "engine/backend_registry.hpp"
#include "report/report_keys.hpp"

namespace {

struct CapabilityText {
  girtd::Capability bit;
  const char* name;
  const char* means;
};

constexpr CapabilityText kCapabilities[] = {
    {girtd::kDrawsWithDda, "kDrawsWithDda", "runs the preparer and DDA: DDA clocks are counted, Q must be a shift"},
    {girtd::kModelsTime, "kModelsTime", "the SystemC pipeline: modeled time, stage activity, waveforms"},
    {girtd::kSeesSurfaces, "kSeesSurfaces", "the HAD knows each triangle's surface: seams are counted"},
    {girtd::kSamplesTiming, "kSamplesTiming", "`--sample-timing`"},
    {girtd::kRunsRtl, "kRunsRtl", "the Verilated RTL: an RTL build key, RTL signals in waveforms"},
    {girtd::kExactPicture, "kExactPicture", "the yardstick pictures are judged against"},
    {girtd::kExactTiming, "kExactTiming", "the yardstick modeled time is judged against"},
};

void print_backends() {
  std::puts("| back end | what | refuses |\n|---|---|---|");
  for (const girtd::BackendEntry& b : girtd::backend_registry()) {
    std::string refuses;
    for (const girtd::BackendRefusal& r : b.refuses) refuses += (refuses.empty() ? "`" : ", `") + r.option + "`";
    std::printf("| `%s` | %s | %s |\n", b.name.c_str(), b.summary.c_str(), refuses.empty() ? "nothing" : refuses.c_str());
  }
  std::puts("\n| capability | means | who has it |\n|---|---|---|");
  for (const CapabilityText& c : kCapabilities) {
    std::string who;
    for (const girtd::BackendEntry& b : girtd::backend_registry())
      if (b.has(c.bit)) who += (who.empty() ? "" : ", ") + b.name;
    std::printf("| `%s` | %s | %s |\n", c.name, c.means, who.c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--backends") == 0) {
    print_backends();
    return 0;
  }
  std::fputs(girtd::report_keys_markdown(girtd::backend_registry()).c_str(), stdout);
  return 0;
}
