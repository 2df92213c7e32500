// What assimp logs while it imports a model, in three kinds: ignored (what
// follows from the importer never letting assimp read a material library,
// and notes on what is never used here); a warning (the positions and faces
// are still exactly the file's); an error (the geometry is not what the file
// says: a silently wrong picture otherwise). Read from Debian's assimp 5.2.5
// sources and tried on files; the table is in sim/io/README.md.
#pragma once

#include <string>

namespace girtd {

enum class AssimpMessage { kIgnored, kWarning, kError };

// `text` without assimp's "Error, T0: " prefix; `logged_as_error`: assimp's
// Err severity (else Warn). An Err message not listed as harmless is an error.
AssimpMessage classify_assimp_message(const std::string& text, bool logged_as_error);

// "Error, T0: OBJ: ..." -> "OBJ: ...", trailing white space dropped.
std::string strip_assimp_prefix(const std::string& logged);

}  // namespace girtd
