#pragma once
// Limit masks at a dart (an interior vertex where one infinitely sharp edge
// ends), from the dart's own one-ring subdivision matrix.
//
// A dart follows the smooth vertex rule, but its sharp edge's point follows
// the crease rule (the midpoint), so its one-ring matrix is not the smooth
// vertex's and the smooth limit masks (which OpenSubdiv applies at darts)
// are not its limit. Here the matrix is read off one step of the scheme's
// own refinement of a dart ring mesh, and the masks are its left
// eigenvectors: eigenvalue 1 for the position (the centre's row of S^256),
// the subdominant pair for the tangents.

#include "subdiv/core/types.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/rules/limit_mask.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::detail {

/// Tags an infinitely sharp crease on `model` from its centre along the
/// first face's edge leaving it, straight on (through the opposite edge at
/// each vertex of `regular_valence`) to the ring mesh's boundary.
void add_dart(RingMesh& model, Index regular_valence);

/// The limit and tangent masks of a dart, in limit_mask.h's layout over the
/// dart's one-ring, the sharp edge at ring position `neighbourhood.sharp[0]`.
/// Tangent1 x tangent2 points out of the surface.
/// \return false where there are none: a split other than quad and triangle,
///   a valence below 3, a one-ring that is not invariant, or a subdominant
///   pair that does not span a plane.
/// \throws std::bad_alloc if memory runs out.
bool dart_limit_masks(const Scheme& scheme, const VertexNeighbourhood& neighbourhood, LimitMasks& masks);

}  // namespace subdiv::detail
