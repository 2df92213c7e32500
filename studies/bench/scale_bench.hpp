// girtd bench --scale: the simulator's own cost against the size of a real
// input. Generated UV spheres (tools/make_mesh.py, written by the driver
// before the run, none stored) of each size are rendered end to end on
// golden and approx, as a user runs them (tools/girtd render when the driver
// started the bench, else this executable), beside assimp's import of the
// same file alone (girtd_assimp_import: ReadFile, no post-processing, its own
// process) as the yardstick: elapsed time, peak resident memory, wall_s, the
// time per triangle, and the growth exponents fitted over the sizes.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace girtd {

inline const std::vector<long> kDefaultScaleSizes = {10000, 100000, 1000000};

struct ScaleBench {
  nlohmann::json rows;      // one per size, and the fits
  std::string markdown;
  int failures = 0;  // a run that did not finish, or read a different triangle count
};

// The driver's plan: "mesh\tTRIANGLES\tPATH" for each size (tools/prerequisites.sh).
std::vector<std::string> scale_bench_plan_lines(const std::string& out_dir, const std::vector<long>& sizes);

// `runs`: paired runs per size (assimp, golden, approx in turn).
ScaleBench run_scale_bench(const std::string& out_dir, const std::vector<long>& sizes, int runs);

}  // namespace girtd
