// girtd_campaign_front RESULTS.json...: the Pareto front over several sweeps'
// points (a campaign: a coarse grid, then refinements). Prints the valid
// points, merged by name (a name is its merged configuration's hash: the
// same design in two sweeps is one point), as a JSON array, each with
// on_front from the sweeps' own definition (sweep_table.hpp). Exit 2 when a
// file cannot be read.
#include <cstdio>
#include <map>
#include <string>

#include "common/input_error.hpp"
#include "io/json_file.hpp"
#include "sweep/sweep_table.hpp"

int main(int argc, char** argv) {
  using json = nlohmann::json;
  if (argc < 2) {
    std::fprintf(stderr, "usage: girtd_campaign_front RESULTS.json...\n");
    return 2;
  }
  try {
    std::map<std::string, json> by_name;
    for (int i = 1; i < argc; ++i) {
      const json doc = girtd::read_json_file(argv[i]);  // held: the loop reads into it
      for (const json& p : doc.at("points"))
        if (p.at("valid").get<bool>()) by_name[p.at("point").get<std::string>()] = p;
    }
    json points = json::array();
    for (auto& [name, p] : by_name) points.push_back(p);
    girtd::mark_pareto_front(points);
    std::printf("%s\n", points.dump().c_str());
  } catch (const girtd::InputError& e) {
    std::fprintf(stderr, "%s\n", e.formatted().c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "girtd_campaign_front: %s\n", e.what());
    return 2;
  }
  return 0;
}
