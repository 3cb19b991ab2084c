#pragma once
// Object File Format (ASCII): the OFF header with the optional ST, C, N and 4
// prefixes (extra per-vertex values skipped), counts, vertices, and faces
// "n i0 ... i(n-1)" with optional trailing colour values. Binary OFF is
// reported as unsupported.

#include <string>
#include <string_view>

#include "subdiv/io/mesh_io.h"

namespace subdiv {

MeshFile parse_off(std::string_view text, const std::string& path = {});

/// `threads` format the text in parallel (0: all cores); the bytes do not
/// depend on it.
std::string format_off(const PolygonMesh& mesh, std::vector<std::string>* warnings = nullptr, int threads = 0);

}  // namespace subdiv
