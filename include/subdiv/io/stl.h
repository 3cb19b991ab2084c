#pragma once
/// \file
/// STL (STereoLithography), ASCII and binary: a list of triangles, each with
/// its own three positions and a facet normal. Reading welds the corners into
/// shared vertices (ReadOptions::weld_tolerance); writing splits polygons
/// into triangles.

#include <string>
#include <string_view>
#include <vector>

#include "subdiv/io/mesh_io.h"

namespace subdiv {

/// Parses STL, ASCII or binary. A file is read as binary when its size is
/// exactly 84 bytes plus 50 per triangle of the count at byte 80 (so binary
/// files whose header starts with "solid" read correctly), else as ASCII:
/// `solid`, facets of `facet normal`, `outer loop`, three `vertex` lines,
/// `endloop`, `endfacet`, then `endsolid`, keywords in any case. Several
/// solids in one file are read into one mesh. Facet normals are checked to
/// be numbers but not kept (they follow from the triangles); binary
/// attribute bytes are ignored.
/// The corners are welded (ReadOptions::weld_tolerance); a triangle left with
/// two corners on one vertex is left out, and the vertices are numbered in
/// order of first use by the triangles kept, so that none is unused.
/// \param bytes the file's contents.
/// \param path names the source in error messages and SourceLines::path only.
/// \param options the welding tolerance.
/// \return the mesh (triangles over welded vertices), the lines of each
///         face's `facet` and each vertex's first `vertex` (none for binary
///         files), and notes: how many triangles welding collapsed, and how
///         many corners a positive tolerance moved onto another position.
/// \throws ParseError naming \p path and the line (ASCII) or the triangle
///         (binary) when the contents are malformed: not STL, bad or
///         non-finite coordinates, a facet without three vertices, no
///         `endsolid`, text after it.
/// \throws std::bad_alloc if memory runs out.
MeshFile parse_stl(std::string_view bytes, const std::string& path = {}, const ReadOptions& options = {});

/// Serialises a mesh as STL. Faces of more than three corners are split into
/// triangles as fans from their first corner, faces of fewer are left out
/// (a note for each). Each facet's normal is its triangle's unit normal
/// (zero for a degenerate one). Binary STL stores float32 little-endian,
/// under an 80-byte header that does not start with "solid"; ASCII writes
/// every coordinate in the shortest form that reads back as the same
/// double. Channels have no place in STL (a note for each kind dropped);
/// write_mesh() notes the tags and polylines.
/// \param mesh the mesh to write.
/// \param encoding binary or ASCII.
/// \param warnings receives the notes; may be null; untouched on a throw.
/// \return the file's bytes.
/// \throws InvalidInputError if the mesh fails check_face_arrays(), a
///         triangle's corner has a non-finite coordinate (the reader refuses
///         them), or (binary) a coordinate beyond float's range or more than
///         2^32 - 1 triangles.
/// \throws std::bad_alloc if memory runs out.
std::string format_stl(const PolygonMesh& mesh, StlEncoding encoding, std::vector<std::string>* warnings = nullptr);

}  // namespace subdiv
