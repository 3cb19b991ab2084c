#pragma once
// Sharpness and vertex rules of one level, the same for every scheme:
// infinitely sharp and semi-sharp creases and corners (DeRose, Kass and
// Truong 1998, "Subdivision surfaces in character animation", section 3, as
// OpenSubdiv's Sdc::Crease implements them with its uniform creasing method).
//
// - Boundary, non-manifold and inconsistently oriented edges are infinitely
//   sharp; so is a boundary vertex with a single face in edge-and-corner
//   mode, an isolated vertex, and a non-manifold vertex unless it lies on
//   exactly two sharp edges (a non-manifold crease).
// - One level down, a sharpness s becomes s - 1 (infinite stays infinite).
// - An edge point uses the crease rule for s >= 1, the smooth rule for
//   s <= 0, and (1 - s) smooth + s crease in between.
// - A vertex's rule follows from its own sharpness and the number of sharp
//   edges around it (corner, or 0/1/2/3+ sharp edges: smooth, dart, crease,
//   corner). Where the rule one level down differs, the vertex point blends
//   the two masks, with weight w on the parent's rule: the mean parent
//   sharpness of the edges (and the vertex) that stop being sharp, at most 1.

#include <span>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

struct LevelCreasing {
  /// This level's edge sharpness; empty when no edge is sharp (the common
  /// closed smooth mesh, which then needs no array).
  std::vector<double> edge_sharpness;
  std::vector<VertexRule> vertex_rule;       ///< from this level's sharpness
  std::vector<VertexRule> child_vertex_rule; ///< from the sharpness one level down
  /// w where the two rules differ, else 1; empty when no rule differs.
  std::vector<double> parent_rule_weight;
};

/// OpenSubdiv's uniform rule for a sharpness one level down.
double subdivide_sharpness(double s);

/// The sharpness of edge e (0 when the level has no sharp edge).
inline double edge_sharpness_of(const LevelCreasing& c, Index e) {
  return c.edge_sharpness.empty() ? 0.0 : c.edge_sharpness[static_cast<std::size_t>(e)];
}

/// The rule for a vertex of this sharpness whose edges have these sharpnesses.
VertexRule vertex_rule_for(double vertex_sharpness, int sharp_edge_count);

LevelCreasing compute_creasing(const PolygonMesh& mesh, const MeshTopology& topology, BoundaryInterpolation boundary);

}  // namespace subdiv
