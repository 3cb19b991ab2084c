#pragma once
// Stanford PLY: ASCII, binary_little_endian and binary_big_endian. Reads the
// vertex element's x, y, z (any numeric type), nx/ny/nz (vertex channel
// "normal"), red/green/blue (channel "color", uchar values scaled to [0, 1])
// and u/v, s/t or texture_u/texture_v (channel "uv"); the face element's
// vertex_indices (or vertex_index) list. Every other element and property is
// skipped. Header counts are checked against the file size before any
// allocation, so a lying header cannot exhaust memory.

#include <string>
#include <string_view>

#include "subdiv/io/mesh_io.h"

namespace subdiv {

MeshFile parse_ply(std::string_view bytes, const std::string& path = {});

/// `threads` format ASCII text in parallel (0: all cores); the bytes do not
/// depend on it.
std::string format_ply(const PolygonMesh& mesh, PlyEncoding encoding,
                       std::vector<std::string>* warnings = nullptr, int threads = 0);

}  // namespace subdiv
