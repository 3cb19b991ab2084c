#pragma once
/// \file
/// Splitting polygons into triangles, for triangle-only schemes (Loop).

#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv {

/// Fans every face of n > 3 corners from its first corner into n - 2
/// triangles (exact for convex faces). Positions, vertex channels, crease and
/// corner tags and the options are kept; face-varying indices follow their
/// corners; a hole face's triangles are holes (hole tags naming no face are
/// dropped). Triangles and faces of fewer than 3 corners are copied
/// unchanged. Polylines are not copied, and raw tags (Tags::other) are
/// copied verbatim although face numbers change.
/// \param mesh the mesh to triangulate.
/// \return the triangulated mesh; its faces follow the input's order.
/// \throws InvalidInputError if the mesh fails check_indices().
/// \throws std::bad_alloc if memory runs out.
PolygonMesh triangulate(const PolygonMesh& mesh);

}  // namespace subdiv
