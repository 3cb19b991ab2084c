#pragma once
/// \file
/// Stanford PLY: ASCII, binary_little_endian and binary_big_endian. Reads the
/// vertex element's x, y, z (any numeric type), nx/ny/nz (vertex channel
/// "normal"), red/green/blue (channel "color", uchar values scaled to [0, 1])
/// and u/v, s/t or texture_u/texture_v (channel "uv"); the face element's
/// vertex_indices (or vertex_index) list. Every other element and property is
/// skipped. Header counts are checked against the file size before any
/// allocation, so a lying header cannot exhaust memory.

#include <string>
#include <string_view>

#include "subdiv/io/mesh_io.h"

namespace subdiv {

/// Parses a PLY file (any of the three encodings).
/// \param bytes the file's contents.
/// \param path names the source in error messages and SourceLines::path only.
/// \return the mesh, its source lines (for the ASCII encoding) and notes
///         about what was not kept.
/// \throws ParseError naming \p path (and the line where there is one) when
///         the contents are malformed.
/// \throws std::bad_alloc if memory runs out.
MeshFile parse_ply(std::string_view bytes, const std::string& path = {});

/// Serialises a mesh as PLY: positions as doubles, faces, and the vertex
/// channels "normal" (3), "uv" (2) and "color" (3, written as bytes) when
/// their sizes fit; other channels are noted in \p warnings. Tags and
/// polylines are left out silently; hole faces are written as ordinary
/// faces.
/// \param mesh the mesh to write.
/// \param encoding ASCII or binary, and the byte order.
/// \param warnings receives a note per channel not written; may be null.
/// \param threads format ASCII text in parallel (0: all cores); the bytes
///        do not depend on it.
/// \return the PLY file's bytes.
/// \throws InvalidInputError if the mesh fails check_face_arrays().
/// \throws std::bad_alloc if memory runs out.
std::string format_ply(const PolygonMesh& mesh, PlyEncoding encoding,
                       std::vector<std::string>* warnings = nullptr, int threads = 0);

}  // namespace subdiv
