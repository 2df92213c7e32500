// Model files checked before assimp reads them, for the formats this project
// reads (OBJ, OFF, PLY, STL): every count in the file that would size an
// allocation (header counts, PLY list lengths, OFF face sizes) is checked
// against the limits and the bytes the file has, and the errors a text file
// can place (a bad vertex index, a NaN coordinate) get their line. Throws
// InputError "FILE:LINE: what" (no line for binary files: they have none;
// the message gives the byte offset).
#pragma once

#include <cstdint>
#include <string>

namespace girtd {

// ".obj", ".off", ".ply", ".stl" (lower case): the formats with a check here.
bool is_checked_model_format(const std::string& lower_ext);

// Dispatches on the extension; `size` is the file's size in bytes.
void precheck_model(const std::string& path, const std::string& lower_ext, uint64_t size);

// The PLY check (ply_precheck.cpp): header, then every element instance, so
// no list length reaches assimp unchecked.
void precheck_ply(const std::string& path, uint64_t size);

}  // namespace girtd
