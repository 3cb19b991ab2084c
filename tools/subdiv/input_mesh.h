#pragma once
// What the commands that refine a mesh file do with it first.

#include "subdiv/io/mesh_io.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::cli {

/// --triangulate, for schemes that read triangles. The faces are
/// renumbered, so their (and the holes') line numbers are dropped: errors
/// about them then name the element without a line.
void triangulate_if_asked(const Scheme& scheme, bool triangulate, MeshFile& file);

}  // namespace subdiv::cli
