#pragma once
/// \file
/// Object File Format (ASCII): the OFF header with the optional ST, C, N and 4
/// prefixes (extra per-vertex values skipped), counts, vertices, and faces
/// "n i0 ... i(n-1)" with optional trailing colour values. Binary OFF is
/// reported as unsupported.

#include <string>
#include <string_view>

#include "subdiv/io/mesh_io.h"

namespace subdiv {

/// Parses OFF text.
/// \param text the file's contents.
/// \param path names the source in error messages and SourceLines::path only.
/// \return the mesh, its source lines and notes about what was not kept.
/// \throws ParseError naming \p path and the line when the text is
///         malformed or is binary OFF.
/// \throws std::bad_alloc if memory runs out.
MeshFile parse_off(std::string_view text, const std::string& path = {});

/// Serialises a mesh's positions and faces as OFF text; OFF has no place for
/// channels, tags or polylines (channels are noted in \p warnings; tags and
/// polylines are left out silently). Hole faces are written as ordinary
/// faces.
/// \param mesh the mesh to write.
/// \param warnings receives a note per channel not written; may be null.
/// \param threads format the text in parallel (0: all cores); the bytes do
///        not depend on it.
/// \return the OFF text.
/// \throws InvalidInputError if the mesh fails check_face_arrays().
/// \throws std::bad_alloc if memory runs out.
std::string format_off(const PolygonMesh& mesh, std::vector<std::string>* warnings = nullptr, int threads = 0);

}  // namespace subdiv
