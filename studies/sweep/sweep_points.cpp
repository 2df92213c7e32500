#include "sweep/sweep_points.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "accuracy/config_variants.hpp"
#include "common/input_error.hpp"
#include "config/params.hpp"
#include "cost/hardware_cost.hpp"
#include "io/sha256.hpp"
#include "sweep/dda_cells.hpp"

namespace girtd {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

json cost_json(const HardwareCost& c) {
  return {{"cost", c.cost},
          {"cost_dda_chips", c.dda_chips},
          {"cost_fifo_chips", c.fifo_chips},
          {"cost_had_chips", c.had_chips},
          {"cost_vram_chips", c.vram_chips},
          {"cost_board_chips", c.board_chips},
          {"ep_register_bits", c.ep_register_bits},
          {"adder_bits", c.adder_bits},
          {"fifo_bits", c.fifo_bits},
          {"cache_bits", c.cache_bits},
          {"write_behind_bits", c.write_behind_bits},
          {"prefetch_bits", c.prefetch_bits},
          {"front_end_boards", c.front_end_boards},
          {"dda_clock_class", c.dda_clock_class},
          {"had_clock_class", c.had_clock_class}};
}

}  // namespace

std::vector<SweepPoint> sweep_points(const SweepSpec& spec, const std::string& dir) {
  const fs::path points_dir = fs::path(dir) / "points";
  fs::create_directories(points_dir);
  std::vector<SweepPoint> out;
  for (size_t index = 0; index < spec.point_count(); ++index) {
    SweepPoint pt;
    pt.axis_values = json::object();
    pt.settings = json::object();
    size_t rest = index;
    for (auto a = spec.axes.rbegin(); a != spec.axes.rend(); ++a) {  // the last axis varies fastest
      const size_t i = rest % a->values.size();
      rest /= a->values.size();
      pt.axis_values[a->name] = a->values[i];
      pt.settings.update(a->settings(i));
    }
    const ConfigVariant variant{"", pt.settings};
    const std::string override_text = variant.override_json().dump(2) + "\n";
    // Slurm tasks write the same points at once: a name of this process's.
    const fs::path tmp = points_dir / ("pending_" + std::to_string(getpid()) + "_" + std::to_string(index) + ".json");
    std::ofstream(tmp) << override_text;
    std::vector<std::string> files = spec.base;
    files.push_back(tmp.string());
    try {
      const Params p = Params::from_files(files);
      pt.id = config_key(p);
      pt.cost = cost_json(hardware_cost(p));
      const std::optional<long> cells = dda_cells(p, points_dir.string());
      pt.cost["cost_yosys_dda_cells"] = cells ? json(*cells) : json();
    } catch (const InputError& e) {
      std::string base_text;
      for (const std::string& b : spec.base) base_text += b + "\n";
      pt.id = sha256_hex(base_text + override_text).substr(0, 16);
      pt.invalid = e.what();  // the key and why, without the scratch file's name
    }
    pt.config_file = (points_dir / (pt.id + ".json")).string();
    fs::rename(tmp, pt.config_file);
    out.push_back(pt);
  }
  return out;
}

}  // namespace girtd
