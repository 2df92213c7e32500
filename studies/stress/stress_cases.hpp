// The generated extreme inputs of `girtd stress` (docs/interface.md),
// family by family. A case is a triangle trace or a scene (nearplane, through
// the front end); the `order` family's cases carry the same triangles in
// every vertex order, which must all draw one picture.
#pragma once

#include <string>
#include <vector>

#include "common/types.hpp"

namespace girtd {

struct StressCase {
  std::string family, name;  // name: unique within the run, a file stem
  std::string what;          // one line for the table
  bool fast = false;         // in the CTest subset
  bool scene = false;        // `text` is a scene (JSON) rather than a triangle trace
  std::string text;
  std::vector<std::string> reorders;  // order family: more traces that must draw the same picture
};

// Every family's name, in the contract's order.
const std::vector<std::string>& stress_families();

// The cases of `family` (a name from stress_families()). `models_dir`: where
// the scenes find their model files (traces/models).
std::vector<StressCase> stress_cases(const std::string& family, const std::string& models_dir);

// A triangle trace: one frame of `tris` with antialiasing width `q`.
std::string triangle_trace(const std::vector<Triangle>& tris, double q, const std::string& comment);

}  // namespace girtd
