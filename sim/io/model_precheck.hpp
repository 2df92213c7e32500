// Model files checked before assimp reads them, for the formats this project
// reads (OBJ, OFF, PLY, STL): every count in the file that would size an
// allocation (header counts, PLY list lengths, OFF face sizes) is checked
// against the limits and the bytes the file has, and the errors a text file
// can place (a bad vertex index, a NaN coordinate) get their line; what
// Debian's assimp 5.2.5 would read silently wrong is refused (each check
// names the assimp behaviour it guards). Throws InputError "FILE:LINE: what"
// or, for binary files, "FILE:@OFFSET: what".
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace girtd {

// ".obj", ".off", ".ply", ".stl" (lower case): the formats with a check here.
bool is_checked_model_format(const std::string& lower_ext);

struct PrecheckResult {
  uint64_t polygons = 0;  // faces of 3 or more corners, for checking what assimp returns against
  // OBJ: the names `usemtl` gives that no material library defines. assimp
  // makes a grey material up for each; they are drawn with the default.
  std::set<std::string> undefined_materials;
};

// The file's first `size` bytes (fewer if it is shorter now).
std::string read_model_bytes(const std::string& path, uint64_t size);

// Reads the file once (`size` bytes) and dispatches on the extension;
// appends what it can go on from (an OBJ's missing material library) to
// `warnings`.
PrecheckResult precheck_model(const std::string& path, const std::string& lower_ext, uint64_t size,
                              std::vector<std::string>& warnings);

// The OBJ check (obj_precheck.cpp): every v and f statement; the material
// libraries' warnings.
PrecheckResult precheck_obj(const std::string& path, const std::string& text, std::vector<std::string>& warnings);

// The PLY check (ply_precheck.cpp): header, then every element instance, so
// no list length reaches assimp unchecked. Returns the polygons.
uint64_t precheck_ply(const std::string& path, const std::string& data);

// The STL check (stl_precheck.cpp): a binary file's size and coordinates, an
// ASCII file read as assimp reads it. Returns the triangles.
uint64_t precheck_stl(const std::string& path, const std::string& data);

// The glTF check (gltf_precheck.cpp), .gltf and .glb: every accessor within
// its buffer view, every view within its buffer, known accessor and
// component types. Counts nothing: assimp's own checks follow.
void precheck_gltf(const std::string& path, const std::string& data);

}  // namespace girtd
