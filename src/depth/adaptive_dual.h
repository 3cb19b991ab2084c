#pragma once
// Adaptive refinement of the dual split, and of midedge, whose two steps make
// one (docs/depth.md, "Adaptive refinement of the dual split"). No child face of a dual split lies inside one parent
// face: a face f gives its F-face, an edge its E-face and a vertex its
// V-face, made of the corner points of the faces around them. So instead of
// a face hierarchy, a level-(j + 1) face exists where every level-j face it is
// made from is split, and the levels are joined by transitions of their own:
// half an E-face between a split face and a leaf, and a fan polygon at a
// vertex whose faces are partly split.

#include "subdiv/depth/adaptive.h"

namespace subdiv::detail {

/// adaptive_refine() for a scheme of the dual split (Doo-Sabin, gcc and
/// midpoint of even degree), or midedge in levels of two steps, on a closed
/// manifold mesh.
/// \param mesh The control mesh.
/// \param scheme The scheme.
/// \param eps The accuracy, positive.
/// \param options The refinement rules and the deepest level.
/// \return The conforming mesh with its vertices' sources and distances.
/// \throws InvalidInputError for an open or non-manifold mesh, more than
///         `options.max_level` levels, and as adaptive_refine() does.
AdaptiveResult adaptive_refine_dual(const PolygonMesh& mesh, const Scheme& scheme, double eps,
                                    const AdaptiveOptions& options);

}  // namespace subdiv::detail
