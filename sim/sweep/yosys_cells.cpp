#include "sweep/yosys_cells.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "layout/rtl_package.hpp"
#include "io/subprocess.hpp"

namespace girtd {
namespace fs = std::filesystem;

bool yosys_available() { return run_process({"yosys", "-V"}, true) == 0; }

std::optional<long> dda_yosys_cells(const Params& p, const std::string& cache_dir) {
  // The DDA reads the EP formats, nf's fractions and its output latency.
  const nlohmann::json built = rtl_build_values(p);
  const nlohmann::json dda_values = {{"ep", built["ep"]}, {"nf", built["nf"]}, {"dda", built["dda"]}};
  const fs::path cache = fs::path(cache_dir) / ("yosys_dda_" + rtl_build_key(dda_values) + ".txt");
  if (long cells = 0; std::ifstream(cache) >> cells) return cells;
  if (!yosys_available()) return std::nullopt;

  const fs::path work = fs::path(cache_dir) / ("yosys_work_" + std::to_string(getpid()));
  fs::create_directories(work);
  std::ofstream(work / "girtd_pkg.sv") << sv_package_text(p);
  std::ofstream(work / "dda_prom_table.svh") << sv_prom_table_text(p);
  const std::string hw = std::string(GIRTD_SOURCE_DIR) + "/hw/dda/";
  std::string sources = (work / "girtd_pkg.sv").string();
  for (const char* f : {"dda_ep.sv", "dda_counter.sv", "dda_saturate.sv", "dda_norm.sv", "dda_nf.sv", "dda_limits.sv",
                        "dda.sv"})
    sources += " " + hw + f;
  const fs::path stat = work / "stat.txt";
  const std::string script = "read_verilog -sv -I" + work.string() + " " + sources +
                             "; chparam -set WRAP_DETECT 0 dda; synth -top dda -flatten; tee -o " + stat.string() +
                             " stat";
  const fs::path log = work.string() + ".log";  // kept when yosys fails
  if (run_process_logged({"yosys", "-q", "-p", script}, log.string()) != 0) {
    fs::remove_all(work);
    return std::nullopt;
  }
  std::ifstream in(stat);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::optional<long> cells;
  const std::regex re(R"(Number of cells:\s+(\d+))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
    cells = std::stol((*it)[1]);  // the last: the flattened top
  fs::remove_all(work);
  if (!cells) return std::nullopt;
  fs::remove(log);
  const fs::path tmp = cache.string() + ".tmp" + std::to_string(getpid());
  std::ofstream(tmp) << *cells << "\n";
  fs::rename(tmp, cache);  // Slurm tasks may race: each writes whole
  return cells;
}

}  // namespace girtd
