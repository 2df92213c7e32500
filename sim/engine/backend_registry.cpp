#include "engine/backend_registry.hpp"

#include <stdexcept>

#include "backends/golden_backend.hpp"
#include "backends/reference_backend.hpp"
#include "backends/approx_backend.hpp"
#include "report/report_keys.hpp"
#include "rtl/backend_rtl.hpp"
#include "timeline/series_switch.hpp"

namespace girtd {

namespace {

std::vector<BackendEntry> make_registry() {
  const BackendRefusal kNoWave{"--wave", "waveforms record the SystemC pipeline: use --backend rtl (or approx)"};
  const BackendRefusal kNoSampling{"--sample-timing",
                                   "sampled timing is an estimator of the approx back end: use --backend approx"};
  std::vector<BackendEntry> r;

  BackendEntry reference;
  reference.name = "reference";
  reference.summary = "double-precision rasterizer: exact edge distances, exact planes";
  reference.capabilities = kSeesSurfaces | kExactPicture;
  reference.refuses = {kNoWave, kNoSampling};
  reference.make = [](const Params& p, const BackendRequest&) { return std::make_unique<ReferenceBackend>(p); };
  r.push_back(std::move(reference));

  BackendEntry golden;
  golden.name = "golden";
  golden.summary = "bit-exact preparer + DDA + HAD models, functional (counts DDA clocks)";
  golden.capabilities = kDrawsWithDda | kSeesSurfaces;
  golden.refuses = {kNoWave, kNoSampling};
  golden.make = [](const Params& p, const BackendRequest&) { return std::make_unique<GoldenBackend>(p); };
  r.push_back(std::move(golden));

  BackendEntry approx;
  approx.name = "approx";
  approx.summary = "SystemC pipeline, golden DDA and HAD, the memory side's timing model";
  approx.capabilities = kDrawsWithDda | kModelsTime | kSeesSurfaces | kSamplesTiming;
  approx.make = [](const Params& p, const BackendRequest& q) { return make_approx_backend(p, q.sample_rate); };
  r.push_back(std::move(approx));

  BackendEntry rtl;
  rtl.name = "rtl";
  rtl.summary = "SystemC pipeline with the Verilated DDA, FIFO, HAD, cache and VRAM";
  rtl.capabilities = kDrawsWithDda | kModelsTime | kRunsRtl | kExactTiming;
  rtl.refuses = {kNoSampling};
  rtl.make = [](const Params& p, const BackendRequest& q) -> std::unique_ptr<Backend> {
    std::unique_ptr<BackendRtl> engine = make_backend_rtl(p, 0, q.traced);
    if (record_series()) engine->record_screen_maps();
    return engine;
  };
  r.push_back(std::move(rtl));
  return r;
}

}  // namespace

const std::vector<BackendEntry>& backend_registry() {
  static const std::vector<BackendEntry> r = make_registry();
  return r;
}

std::vector<std::string> backend_names() {
  std::vector<std::string> out;
  for (const BackendEntry& b : backend_registry()) out.push_back(b.name);
  return out;
}

const BackendEntry* find_backend(const std::string& name) {
  for (const BackendEntry& b : backend_registry())
    if (b.name == name) return &b;
  return nullptr;
}

const BackendEntry& backend_named(const std::string& name) {
  if (const BackendEntry* b = find_backend(name)) return *b;
  throw std::logic_error("not a registered back end: " + name);
}

const BackendEntry& backend_with(Capability c) {
  for (const BackendEntry& b : backend_registry())
    if (b.has(c)) return b;
  throw std::logic_error("no registered back end has capability " + std::to_string(unsigned(c)));
}

std::vector<std::string> not_modeled(const BackendEntry& b) { return not_modeled_keys(b.capabilities); }

}  // namespace girtd
