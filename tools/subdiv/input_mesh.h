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

/// One warning line when the mesh has tags that refining it `levels` levels
/// does not apply (OBJ `t` lines kept verbatim): refined meshes drop them,
/// since their indices name the input's faces and vertices. Hierarchical
/// edits are applied where `scheme` is given and takes them
/// (applies_hierarchical_edits()) and they lie within the levels made.
/// Says how many of each kind, e.g. "2 vertexedit, 1 edgeedit".
/// \throws InvalidInputError naming `path` where an edit tag is malformed.
void warn_dropped_tags(const std::string& path, const PolygonMesh& mesh, const Scheme* scheme = nullptr,
                       int levels = 0);

/// Input normals (OBJ `vn`, PLY nx ny nz) would be interpolated as data by
/// refinement, not follow the refined surface: removes them from `mesh`,
/// with one warning line naming the file, when there are any.
void drop_input_normals(const std::string& path, PolygonMesh& mesh);

}  // namespace subdiv::cli
