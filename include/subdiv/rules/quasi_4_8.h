#pragma once
// Quasi 4-8 subdivision (L. Velho): the bisection split of
// subdiv/topology/bisection_split.h, then the smoothing of Algorithm 2 in
// two passes, every weight in quasi_4_8.cpp. One refinement step is one
// binary step; two make a 4-8 step.
//
// The masks are over the child level: pass 1 gives a new vertex (a split
// point) weights over old vertices, whose values are still their parent
// positions; pass 2 gives an old vertex weight on itself (its parent
// position) and, through MaskBuilder::add_face_point(i), on new vertex
// old_vertex_count + i after pass 1. Evaluated in that order the masks are
// Algorithm 2 in place; composed, they are the stencils of the paper's
// Figure 4 (tests/rules/quasi_4_8_test.cpp).

#include <span>
#include <vector>

#include "subdiv/rules/scheme.h"
#include "subdiv/topology/bisection_split.h"

namespace subdiv {

const char* to_string(Quasi48Boundary);

const Scheme& quasi_4_8_scheme();

/// What the masks of one step see.
struct Quasi48Level {
  const MeshTopology& child;  ///< the bisected level
  const BisectionMap& map;
  /// Per child vertex: not smoothed (a tagged vertex, an end of a tagged
  /// edge, a fixed boundary vertex). A fixed split point stays at its
  /// edge's midpoint; a fixed old vertex at its position.
  std::span<const char> fixed;
  /// The parent edges' ends, for a fixed split point's midpoint.
  const MeshTopology& parent;
};

/// The child vertices smoothing leaves in place: corner-tagged vertices,
/// the ends of crease-tagged edges (any sharpness > 0: the paper's tags are
/// on or off), and under Quasi48Boundary::fixed every boundary vertex.
std::vector<char> quasi_4_8_fixed_vertices(const PolygonMesh& child, const MeshTopology& child_topology,
                                           Quasi48Boundary boundary);

/// Pass 1 for new vertex v (map.is_new(v)): weights over old vertices.
void quasi_4_8_new_vertex_mask(const Quasi48Level& level, Index v, MaskBuilder& mask);
/// Pass 2 for old vertex v: weight on v itself (add) and on pass 1's new
/// vertices (add_face_point(i) for child vertex map.old_vertex_count + i).
void quasi_4_8_old_vertex_mask(const Quasi48Level& level, Index v, MaskBuilder& mask);

}  // namespace subdiv
