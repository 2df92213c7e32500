#include "io/assimp_messages.hpp"

#include <cctype>

namespace girtd {
namespace {

bool starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

// Err messages that follow from material libraries being kept from assimp
// (model_import.cpp): the OBJ pre-check says what is missing, once.
constexpr const char* kFromNoLibraries[] = {
    "OBJ: Unable to locate material file",           // every mtllib
    "OBJ: Unable to locate fallback material file",  // NAME.mtl beside the model
    "OBJ: failed to locate material",                // every usemtl: a new default material
    "OBJ: No object detected to attach a new mesh instance",  // usemtl before any face: that mesh stays empty,
                                                               // the first face makes the object its faces go to
};

// Warn messages about what is never used here (texture coordinates,
// materials) or legitimate in the format (OFF and PLY vertices no face
// uses; a lost face is caught by the polygon count instead).
constexpr const char* kQuietWarnings[] = {
    "ScenePreprocessor:",  // "UVs are declared to be 3D but they're obviously not" ("vt u v 0")
    "Validation warning: There are unreferenced vertices",
    "Validation warning: Invalid opacity value",
    "Validation warning: UV-mapped texture",
    "Validation warning: Invalid UV index",
    "Validation warning: A specular shading model",
};

// Err messages after which the positions and faces are still the file's.
constexpr const char* kHarmlessErrors[] = {
    "Obj: Ignoring empty face",                       // an "f" with no corners
    "Obj: Separator unexpected in point statement",  // "p 1/2": a point, never drawn
    "FBX: no material assigned to mesh, setting default material",  // materials are not used
    "FBX: ignoring additional binormal layer",                       // nor binormals
    "FBX: ignoring additional tangent layer",                        // nor tangents
    "3DS: Skipping FOV animation track",                             // nor animations
};

// Warn messages that mean a value or a face is not what the file says.
constexpr const char* kGeometryWarnings[] = {
    "Unable to parse property instance",         // PLY: missing values read as 0, a 0 index added to lists
    "Unable to parse binary property instance",  // the same, binary
    "Converting the string",                     // "... into a value resulted in overflow": the number becomes 0
    "STL: A new facet begins but the old is not yet complete",
    "STL: a facet normal vector was expected but not found",
    "STL: mesh is empty or invalid; no data loaded",
};

}  // namespace

AssimpMessage classify_assimp_message(const std::string& text, bool logged_as_error) {
  if (logged_as_error) {
    for (const char* p : kFromNoLibraries)
      if (starts_with(text, p)) return AssimpMessage::kIgnored;
    for (const char* p : kHarmlessErrors)
      if (starts_with(text, p)) return AssimpMessage::kWarning;
    return AssimpMessage::kError;
  }
  for (const char* p : kGeometryWarnings)
    if (starts_with(text, p)) return AssimpMessage::kError;
  for (const char* p : kQuietWarnings)
    if (starts_with(text, p)) return AssimpMessage::kIgnored;
  return AssimpMessage::kWarning;
}

std::string strip_assimp_prefix(const std::string& logged) {
  std::string msg = logged;
  const size_t colon = msg.find(": ");
  if (colon != std::string::npos && (starts_with(msg, "Error,") || starts_with(msg, "Warn,")))
    msg = msg.substr(colon + 2);
  while (!msg.empty() && std::isspace(static_cast<unsigned char>(msg.back()))) msg.pop_back();
  return msg;
}

}  // namespace girtd
