#pragma once
// A level's linear surface at the vertices one period of a rotating split
// down. One step of the sqrt3 or sqrt2 split makes child faces that straddle
// the parent's edges, but two steps nest: the sqrt3 split's second child
// level is the parent's triangles split 1-to-9 (the edges trisected), the
// sqrt2 split's is the parent's quads split 1-to-4 (docs/depth.md,
// "Interpolating schemes on the sqrt3 and sqrt2 splits"). Every vertex two
// steps down then has a parameter on the level's surface: a corner, a face
// centre (centroid, bilinear centre), or a point of an edge (its thirds for
// the sqrt3 split, its midpoint for the sqrt2 split).

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/topology/split.h"

namespace subdiv::detail {

/// Two steps of \p rule on \p level's faces, every vertex placed on
/// \p level's linear surface (flat triangles for the sqrt3 split, bilinear
/// quads for the sqrt2 split) at its parameter. Its faces and numbering are
/// the split's, as refine() makes them; its own linear surface is \p level's
/// restricted to the finer faces, so applying it again gives \p level's
/// surface two periods down.
/// \param level The level: a triangle mesh (sqrt3) or a closed quad mesh
///        (sqrt2), manifold. Only its positions and faces are read.
/// \param level_number Its level (the sqrt3 split's boundary steps
///        alternate with it).
/// \param rule SplitRule::sqrt3 or SplitRule::sqrt2.
/// \return The two-step mesh (positions and faces; no tags or channels).
/// \throws InvalidInputError for another split, faces of another size, a
///         sqrt2 mesh with a boundary, or an open sqrt3 mesh at an odd level
///         (its first step trisects the boundary, and the second step's
///         triangles at the boundary straddle two of the level's faces).
/// \throws TopologyError as split_topology() does.
/// \throws std::bad_alloc if memory runs out.
PolygonMesh nested_linear_refinement(const PolygonMesh& level, int level_number, SplitRule rule);

}  // namespace subdiv::detail
