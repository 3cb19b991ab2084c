#pragma once
// What the commands that refine a mesh file do with it first.

#include <string>

#include "subdiv/io/mesh_io.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::cli {

/// --triangulate, for schemes that read triangles. The faces are
/// renumbered, so their (and the holes') line numbers are dropped: errors
/// about them then name the element without a line.
void triangulate_if_asked(const Scheme& scheme, bool triangulate, MeshFile& file);

/// One warning line when the mesh has tags no module interprets (OBJ `t`
/// lines such as hierarchical edits): refined meshes drop them, since
/// their indices name the input's faces and vertices. Says how many of each
/// kind, e.g. "2 vertexedit, 1 edgeedit".
void warn_dropped_tags(const std::string& path, const Tags& tags);

/// Input normals (OBJ `vn`, PLY nx ny nz) would be interpolated as data by
/// refinement, not follow the refined surface: removes them from `mesh`,
/// with one warning line naming the file, when there are any.
void drop_input_normals(const std::string& path, PolygonMesh& mesh);

}  // namespace subdiv::cli
