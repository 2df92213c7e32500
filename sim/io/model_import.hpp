// Model files through assimp: OBJ, OFF, PLY and STL, the formats whose
// counts model_precheck checks before assimp reads them (other formats are
// refused). Polygons are kept as polygons (no aiProcess_Triangulate: the
// GIRTD triangulator does that). Every problem is an InputError naming the
// file, and the line where the pre-check or assimp's message knows it.
#pragma once

#include <string>
#include <vector>

#include "frontend/mesh.hpp"

namespace girtd {

// Limits on what a model may hold (the importer refuses more rather than
// allocate from a count it cannot trust).
inline constexpr size_t kMaxModelPolygons = 4000000;
inline constexpr size_t kMaxPolygonVertices = 65536;

// Positions are merged when bit-identical, so polygons that share a corner
// share an index (STL repeats every corner). Points and lines are skipped.
// What assimp could go on from without changing the geometry (a missing
// .mtl, an unknown material: materials in model files are not used) is
// appended to `warnings` as "FILE: what"; anything that would change the
// positions or polygons is an InputError (sim/io/README.md lists which).
Mesh import_model(const std::string& path, std::vector<std::string>& warnings);

bool is_model_file(const std::string& path);  // by extension: .obj, .off, .ply, .stl (any case)

// For a file that is not a model file: InputError "this format is not read"
// when its extension names another format assimp knows (.3ds, .fbx, ...).
void reject_other_model_formats(const std::string& path);

}  // namespace girtd
