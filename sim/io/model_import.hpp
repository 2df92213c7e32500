// Model files through assimp: every format it reads (OBJ, OFF, PLY, STL,
// glTF 2.0, Collada, 3DS, FBX, ...), the node hierarchy's transforms
// applied. Polygons are kept as polygons (no aiProcess_Triangulate: the GIRTD
// triangulator does that). Every problem is an InputError naming the file,
// and the line where the pre-check or assimp's message knows it.
//
// OBJ, OFF, PLY and STL are pre-checked first (model_precheck: what Debian's
// assimp 5.2.5 would read silently wrong is refused, with its line); then,
// for every format, assimp runs in a child process under kImportLimits, so
// that a crash, an exhausted memory or a hang inside an importer is one
// error line, not the end of this process (import_child).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/imported_model.hpp"

namespace girtd {

// Limits on what a model may hold (the importer refuses more rather than
// allocate from a count it cannot trust).
inline constexpr size_t kMaxModelPolygons = 4000000;
inline constexpr size_t kMaxPolygonVertices = 65536;

// What the importer's child process may take: a 10^6-triangle file imports
// in about 1.2 s and 242 MB.
struct ImportLimits {
  double seconds;
  uint64_t memory_bytes;  // its address space (not enforced in a sanitized build: ASan reserves terabytes)
};
inline constexpr ImportLimits kImportLimits{60.0, uint64_t(8) << 30};

// Positions are merged when bit-identical, so polygons that share a corner
// share an index (STL repeats every corner). Points and lines are skipped.
// The file's materials, vertex colours, textures' stand-in, cameras and
// lights come along (imported_model.hpp). What assimp could go on from
// without changing the geometry (a missing .mtl, a texture it cannot read)
// is appended to `warnings` as "FILE: what"; anything that would change the
// positions or polygons is an InputError (sim/io/README.md lists which).
ImportedModel import_model(const std::string& path, std::vector<std::string>& warnings);

// The same import in this process: what the child runs (the fuzz targets
// call it, so the fuzzer sees the importer's coverage).
ImportedModel import_model_in_process(const std::string& path, std::vector<std::string>& warnings);

// By extension (any case): a format assimp reads, but .raw (a headerless
// trace may be named so; a scene's "file" still imports a RAW model).
bool is_model_file(const std::string& path);

}  // namespace girtd
