#include "sweep/dda_cells.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "common/file_text.hpp"
#include "layout/rtl_package.hpp"

namespace girtd {
namespace fs = std::filesystem;

namespace {

// The DDA reads the EP formats, nf's fractions and its output latency.
std::string dda_key(const Params& p) {
  const nlohmann::json built = rtl_build_values(p);
  return rtl_build_key(nlohmann::json{{"ep", built["ep"]}, {"nf", built["nf"]}, {"dda", built["dda"]}});
}

fs::path cache_file(const Params& p, const std::string& cache_dir) {
  return fs::path(cache_dir) / ("dda_cells_" + dda_key(p) + ".txt");
}

fs::path request_dir(const Params& p, const std::string& cache_dir) {
  return fs::path(cache_dir) / ("dda_cells_" + dda_key(p));
}

}  // namespace

std::optional<long> dda_cells(const Params& p, const std::string& cache_dir) {
  const fs::path cache = cache_file(p, cache_dir);
  if (long cells = 0; std::ifstream(cache) >> cells) return cells;
  const fs::path request = request_dir(p, cache_dir);
  const std::string stat = read_file_text((request / "stat.txt").string()).value_or("");
  std::optional<long> cells;
  const std::regex re(R"(Number of cells:\s+(\d+))");
  for (auto it = std::sregex_iterator(stat.begin(), stat.end(), re); it != std::sregex_iterator(); ++it)
    cells = std::stol((*it)[1]);  // the last: the flattened top
  if (!cells) return std::nullopt;  // not run, or failed (its log stays in the request folder)
  const fs::path tmp = cache.string() + ".tmp" + std::to_string(getpid());
  std::ofstream(tmp) << *cells << "\n";
  fs::rename(tmp, cache);  // Slurm tasks may race: each writes whole
  fs::remove_all(request);
  return cells;
}

std::optional<std::string> dda_cells_request(const Params& p, const std::string& cache_dir) {
  if (dda_cells(p, cache_dir)) return std::nullopt;
  const fs::path work = request_dir(p, cache_dir);
  fs::create_directories(work);
  std::ofstream(work / "girtd_pkg.sv") << sv_package_text(p);
  std::ofstream(work / "dda_prom_table.svh") << sv_prom_table_text(p);
  const std::string hw = std::string(GIRTD_SOURCE_DIR) + "/hw/dda/";
  std::string sources = (work / "girtd_pkg.sv").string();
  for (const char* f : {"dda_ep.sv", "dda_counter.sv", "dda_saturate.sv", "dda_norm.sv", "dda_nf.sv", "dda_limits.sv",
                        "dda.sv"})
    sources += " " + hw + f;
  std::ofstream(work / "synth.ys") << "read_verilog -sv -I" << work.string() << " " << sources
                                   << "\nchparam -set WRAP_DETECT 0 dda\nsynth -top dda -flatten\ntee -o "
                                   << (work / "stat.txt").string() << " stat\n";
  return work.string();
}

}  // namespace girtd
