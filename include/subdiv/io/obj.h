#pragma once
/// \file
/// Wavefront OBJ: v (optionally with r g b), vt, vn, f in the v, v/vt, v//vn
/// and v/vt/vn forms with negative (relative) indices, l (polylines, v or v/vt;
/// closed when the last index equals the first, which is then not stored),
/// comments, groups, and OpenSubdiv's tag lines:
///
///   t crease N/M/0 a0 b0 a1 b1 ... s...   N/2 edges (a_i, b_i); M = 1 or N/2 sharpnesses
///   t corner N/M/S v... s... [type...]    M = 1 or N sharpnesses; S = 0, 1 or N
///                                         types: convex | concave, optionally
///                                         ":degrees" (e.g. concave:270)
///   t hole N/0/0 f...                     faces
///   t interpolateboundary 1/0/0 m         0 none, 1 edge-and-corner, 2 edge-only
///   t facevaryinginterpolateboundary 1/0/0 m   0 none .. 5 all (OpenSubdiv order)
///   t facevaryingpropagatecorners 1/0/0 b
///   t creasemethod 0/0/1 normal|chaikin
///   t smoothtriangles 0/0/1 catmark|smooth
///
/// Indices in tags are 0-based, as OpenSubdiv writes them. Any other tag
/// (vertexedit, edgeedit, faceedit...) is kept verbatim and written back.
/// `vt` coordinates become the face-varying channel "uv" (2 components),
/// `vn` the face-varying channel "normal", vertex colours the vertex channel
/// "color"; a channel that only some faces use is dropped with a warning.

#include <string>
#include <string_view>

#include "subdiv/io/mesh_io.h"

namespace subdiv {

/// Parses OBJ text.
/// \param text the file's contents.
/// \param path names the source in error messages and SourceLines::path only.
/// \return the mesh, its source lines and notes about what was not kept.
/// \throws ParseError naming \p path and the line when the text is malformed.
/// \throws std::bad_alloc if memory runs out.
MeshFile parse_obj(std::string_view text, const std::string& path = {});

/// Serialises a mesh as OBJ text (shortest round-trip decimal numbers).
/// Writes the vertex channel "color" (3 components) and the face-varying
/// channels "uv" (2 or 3 components) and "normal" (3 components); other
/// channels are noted in \p warnings. WriteOptions::ply_encoding and
/// WriteOptions::hole_faces_as_faces are not read (OBJ keeps holes as tags).
/// \param mesh the mesh to write.
/// \param options what to write, and how many threads format the text.
/// \param warnings receives a note per channel not written; may be null.
/// \return the OBJ text.
/// \throws InvalidInputError if the mesh fails check_indices(), or a raw
///         tag's name or string is empty or holds white space.
/// \throws std::bad_alloc if memory runs out.
std::string format_obj(const PolygonMesh& mesh, const WriteOptions& options = {},
                       std::vector<std::string>* warnings = nullptr);

}  // namespace subdiv
