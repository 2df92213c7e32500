// Model files through assimp (OBJ, PLY, STL, OFF and the rest it reads),
// polygons kept as polygons (no aiProcess_Triangulate: the GIRTD
// triangulator does that). Every problem is an InputError naming the file
// (and the line, when assimp's message gives one).
#pragma once

#include <string>

#include "frontend/mesh.hpp"

namespace girtd {

// Limits on what a model may hold (the importer refuses more rather than
// allocate from a count it cannot trust).
inline constexpr size_t kMaxModelPolygons = 4000000;
inline constexpr size_t kMaxPolygonVertices = 65536;

// Positions are merged when bit-identical, so polygons that share a corner
// share an index (STL repeats every corner). Points and lines are skipped.
Mesh import_model(const std::string& path);

bool is_model_file(const std::string& path);  // by extension, as assimp would pick its reader

}  // namespace girtd
