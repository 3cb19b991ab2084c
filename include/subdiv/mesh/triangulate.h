#pragma once
// Splitting polygons into triangles, for triangle-only schemes (Loop).

#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv {

/// Fans every face of n > 3 corners from its first corner into n - 2
/// triangles (exact for convex faces). Positions, vertex channels, crease and
/// corner tags are kept; face-varying indices follow their corners; a hole
/// face's triangles are holes. Triangles are copied unchanged.
PolygonMesh triangulate(const PolygonMesh& mesh);

}  // namespace subdiv
