#pragma once
// The grid path of refine(): the remaining levels of a quad- or
// triangle-split scheme that declares its regular rule
// (FastPath::regular_grid or regular_grid_of, FastPath::regular_triangle_grid),
// made in one go.
//
// Each face of the starting level (all quads, or all triangles) refines on
// its own. A face whose corners are interior vertices of the regular
// valence (4 or 6) with no sharp edge or corner tag is a regular patch: its
// control points (4 x 4, up to 8 x 8 for wider stencils, whose points must
// then all be regular; or the 12 of the triangular lattice) are gathered
// once and refined as a grid by the declared stencil, without any
// intermediate topology. The other faces (extraordinary or sharp corners,
// boundaries) are refined by the masks on a small mesh: those faces and
// rings of faces around them, which hold everything their points read
// (grid_common.h's masks_mesh()). Vertex numbers, faces and tags of the result are computed by
// index arithmetic (grid_numbering.h; triangle_numbering.h, which derives
// light arrays for all but the last two levels), so the result is the
// masks' mesh (the same numbering, tags and face-varying values; positions
// and vertex channels equal up to rounding), written once into its final
// arrays. Each shared point is written by one owning face, so results do
// not depend on the thread count.

#include <optional>

#include "subdiv/core/stencil_table.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::detail {

/// `levels` steps of `scheme` from `level` (its topology `topology`; the
/// mesh's face arrays may have been dropped) through the grid path, or
/// nullopt where it does not apply: a scheme without a regular grid rule,
/// piecewise-smooth rules or non-manifold refinement, a face of the other
/// kind, an isolated vertex, semi-sharp creases with Chaikin's creasing,
/// malformed face-varying channels, more than 8 levels (or, for triangles,
/// fewer than kMinTriangleGridLevels), two triangles on the same three
/// vertices; or where the mesh refined by
/// the masks would hold more than half the faces (the caller then refines
/// one level by the masks and asks again).
std::optional<PolygonMesh> refine_as_grids(const PolygonMesh& level, const MeshTopology& topology,
                                           const Scheme& scheme, const RefineOptions& options, int levels);

/// The same levels as one stencil table, `level`'s vertices -> the last
/// level's (refine_stencil_table()'s rows: merged, sorted by source): a
/// regular face's points as the products of the stencil's line weights over
/// its 16 control points, the others' rows from the masks' mesh. nullopt
/// where refine_as_grids() declines.
std::optional<StencilTable> stencils_as_grids(const PolygonMesh& level, const MeshTopology& topology,
                                              const Scheme& scheme, const RefineOptions& options, int levels);

}  // namespace subdiv::detail
