// Edge flags (thesis 5.2.4's invisible edges): an edge two triangles of one
// surface share side by side — a triangulator diagonal or an edge inside a
// mesh — is interior, and with preparer.edge_flags it gets no antialiasing
// fringe, so a transparent surface shows no seams. A silhouette (the two
// triangles folded onto one side of the edge, front face and back face) keeps
// its fringe. The thesis' database stores the flags with the polygons; here
// they are found per frame from bit-identical screen corners, like the shared
// normals, and not charged as work.
#pragma once

#include <vector>

#include "common/types.hpp"

namespace girtd {

// Sets Triangle::interior_edges of every triangle of the frame.
void mark_interior_edges(std::vector<Triangle>& frame);

}  // namespace girtd
