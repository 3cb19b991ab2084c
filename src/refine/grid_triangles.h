#pragma once
// The grid path (grid_refine.h) of triangle-split schemes that declare
// their regular rule (FastPath::regular_triangle_grid or
// regular_triangle_grid_of): regular triangles
// refined on the triangular lattice (triangle_patch.h), numbered by
// triangle_numbering.h; the others by the masks on a small mesh.

#include <optional>

#include "subdiv/core/stencil_table.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::detail {

// refine_as_grids() and stencils_as_grids() take triangles only from this
// many remaining levels on: with fewer, a face's grid is too small to repay
// its patch and numbering, and the masks are faster (BENCHMARKS.md,
// "Triangles as grids").
constexpr int kMinTriangleGridLevels = 2;

// Up to this many levels, a face's points are evaluated one by one from its
// control points (TrianglePointRows) rather than refined level by level.
constexpr int kDirectTriangleLevels = 2;

// The grid path for any number of levels (1 .. 8), as refine_as_grids()
// and stencils_as_grids() describe it.
std::optional<PolygonMesh> refine_triangles_as_grids(const PolygonMesh& level, const MeshTopology& topology,
                                                     const Scheme& scheme, const RefineOptions& options, int levels);

std::optional<StencilTable> triangle_stencils_as_grids(const PolygonMesh& level, const MeshTopology& topology,
                                                       const Scheme& scheme, const RefineOptions& options, int levels);

}  // namespace subdiv::detail
