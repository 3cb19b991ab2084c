#pragma once
/// \file
/// Sharpness and vertex rules of one level, the same for every scheme:
/// infinitely sharp and semi-sharp creases and corners (DeRose, Kass and
/// Truong 1998, "Subdivision surfaces in character animation", section 3, as
/// OpenSubdiv's Sdc::Crease implements them, with its uniform or its Chaikin
/// creasing method).
///
/// - Boundary, non-manifold and inconsistently oriented edges are infinitely
///   sharp; so is a boundary vertex with a single face in edge-and-corner
///   mode, an isolated vertex, and a non-manifold vertex unless it lies on
///   exactly two sharp edges (a non-manifold crease).
/// - One level down, a sharpness s becomes s - 1 (infinite stays infinite):
///   vertex sharpness always, edge sharpness with the uniform method.
/// - Chaikin creasing (Sdc::Options::CREASE_CHAIKIN, `t creasemethod chaikin`)
///   subdivides a semi-sharp edge's sharpness per end: the child of edge e at
///   its end vertex v gets 3/4 s(e) + 1/4 mean(s of the other semi-sharp edges
///   at v) - 1, at least 0; s(e) - 1 where e is the only semi-sharp edge at v.
///   The two halves of an edge can then differ (child_edge_sharpness).
/// - An edge point uses the crease rule where the edge is sharp and both its
///   children are sharp one level down (uniform: s >= 1), the smooth rule for
///   s <= 0, and (1 - s) smooth + s crease otherwise (edge_crease_weight).
/// - A vertex's rule follows from its own sharpness and the number of sharp
///   edges around it (corner, or 0/1/2/3+ sharp edges: smooth, dart, crease,
///   corner). Where the rule one level down (from the children of its edges at
///   the vertex) differs, the vertex point blends the two masks, with weight w
///   on the parent's rule: the mean parent sharpness of the edges (and the
///   vertex) that stop being sharp, at most 1.

#include <span>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The sharpness and vertex rules of one level (compute_creasing()).
struct LevelCreasing {
  /// This level's edge sharpness; empty when no edge is sharp (the common
  /// closed smooth mesh, which then needs no array).
  std::vector<double> edge_sharpness;
  std::vector<VertexRule> vertex_rule;       ///< from this level's sharpness
  std::vector<VertexRule> child_vertex_rule; ///< from the sharpness one level down
  /// w where the two rules differ, else 1; empty when no rule differs.
  std::vector<double> parent_rule_weight;
  /// Chaikin creasing only: the sharpness one level down of each edge's two
  /// children, the child at end i of edge e (topology.edge_vertices(e)[i])
  /// at 2e + i. Empty with the uniform method, and when the level has no
  /// semi-sharp edge (Chaikin's rule is then the uniform one): every child
  /// is then subdivide_sharpness() of its parent (child_sharpness_of).
  std::vector<double> child_edge_sharpness;
};

/// The sharpness one level down of the children, at vertex v, of the edges
/// around v whose sharpnesses are `parent` (Sdc::Crease::
/// SubdivideEdgeSharpnessesAroundVertex): subdivide_sharpness() with the
/// uniform method; with Chaikin's, a semi-sharp edge's child gets
/// 3/4 s + 1/4 (mean of the other semi-sharp s) - 1, at least 0, or s - 1
/// when it is the only semi-sharp edge. `child` has parent.size() entries.
/// \param method the creasing method.
/// \param parent the sharpness of each edge around the vertex.
/// \param child receives the children's sharpness, entry for entry.
/// \pre child.size() >= parent.size() (unchecked).
void subdivide_sharpness_around_vertex(CreaseMethod method, std::span<const double> parent,
                                       std::span<double> child) noexcept;

/// The sharpness of edge e (0 when the level has no sharp edge).
/// \param c the level's creasing.
/// \param e an edge of the level.
/// \return its sharpness (kInfiniteSharpness for boundary and non-manifold edges).
/// \pre \p e is in [0, edge count) (unchecked).
inline double edge_sharpness_of(const LevelCreasing& c, Index e) noexcept {
  return c.edge_sharpness.empty() ? 0.0 : c.edge_sharpness[static_cast<std::size_t>(e)];
}

/// The sharpness one level down of edge e's child at end `end` (0 or 1,
/// as in topology.edge_vertices(e)).
/// \param c the level's creasing.
/// \param e an edge of the level.
/// \param end 0 or 1: which end's child.
/// \return the child's sharpness.
/// \pre \p e is in [0, edge count) and \p end is 0 or 1 (unchecked).
inline double child_sharpness_of(const LevelCreasing& c, Index e, int end) noexcept {
  if (c.child_edge_sharpness.empty()) return subdivide_sharpness(edge_sharpness_of(c, e));
  return c.child_edge_sharpness[2 * static_cast<std::size_t>(e) + static_cast<std::size_t>(end)];
}

/// The weight of the crease rule in edge e's edge point, the smooth rule
/// getting the rest (Sdc::Scheme::ComputeEdgeVertexMask): 0 for a smooth
/// edge, 1 where both children of the edge stay sharp (uniform: s >= 1), s
/// otherwise. With Chaikin creasing an edge of sharpness s in (1, 4/3) can
/// have a child that decays to 0; OpenSubdiv then weights the crease rule
/// by s > 1 (an affine extrapolation), and so does subdiv.
/// \param c the level's creasing.
/// \param e an edge of the level.
/// \return the crease rule's weight, >= 0.
/// \pre \p e is in [0, edge count) (unchecked).
inline double edge_crease_weight(const LevelCreasing& c, Index e) noexcept {
  const double s = edge_sharpness_of(c, e);
  if (s <= 0.0) return 0.0;
  if (c.child_edge_sharpness.empty()) return s >= 1.0 ? 1.0 : s;
  const std::size_t i = 2 * static_cast<std::size_t>(e);
  return c.child_edge_sharpness[i] > 0.0 && c.child_edge_sharpness[i + 1] > 0.0 ? 1.0 : s;
}

/// The rule for a vertex of this sharpness with this many sharp edges:
/// corner for a sharp vertex, else smooth, dart, crease or corner for 0, 1,
/// 2 or more sharp edges.
/// \param vertex_sharpness the vertex's sharpness (> 0: a corner).
/// \param sharp_edge_count the sharp edges around the vertex.
/// \return the rule.
VertexRule vertex_rule_for(double vertex_sharpness, int sharp_edge_count) noexcept;

/// The creasing of a level whose tags are `mesh.tags` (crease and corner
/// sharpness), under `boundary` and the creasing `method` (the caller's
/// choice: refinement uses the mesh's `creasemethod` tag unless overridden).
/// Crease tags on vertex pairs that are not edges, and corner tags on
/// vertices outside the mesh, are ignored; an edge tagged twice takes the
/// larger sharpness.
/// \param mesh the level (its tags are read).
/// \param topology the topology of \p mesh.
/// \param boundary the boundary interpolation.
/// \param method the creasing method.
/// \param control_level whether \p mesh is the control mesh (level 0):
///        its non-manifold vertices are then sharpened as OpenSubdiv
///        sharpens its base level's (MeshTopology::is_non_manifold_corner();
///        the splits tag their vertex points as corners, so that the
///        sharpness stays). On every level a vertex whose ring is not
///        ordered is a corner unless exactly two of its edges are
///        infinitely sharp.
/// \return the level's creasing.
/// \pre \p topology was built from \p mesh (unchecked).
/// \throws std::bad_alloc if memory runs out.
LevelCreasing compute_creasing(const PolygonMesh& mesh, const MeshTopology& topology, BoundaryInterpolation boundary,
                               CreaseMethod method, bool control_level = false);

/// The weight of the parent's rule where features at vertex v stop being
/// sharp one level down (Sdc::Crease::ComputeFractionalWeightAtVertex): the
/// mean sharpness of what decays among the vertex (sharpness
/// `vertex_sharpness`) and `edges` (edges at v), at most 1; 0 where nothing
/// decays. The vertex rules blend with it over all of v's edges
/// (LevelCreasing::parent_rule_weight); face-varying creases over a region's.
/// \param topology the level's topology.
/// \param creasing the level's creasing.
/// \param v the vertex.
/// \param vertex_sharpness v's sharpness as the rules see it (vertex_sharpness()).
/// \param edges edges at v.
/// \return the weight, in [0, 1].
/// \pre every edge in \p edges has v as an end (unchecked).
double decay_weight(const MeshTopology& topology, const LevelCreasing& creasing, Index v, double vertex_sharpness,
                    std::span<const Index> edges) noexcept;

/// Every vertex's sharpness as the rules see it: its corner tag (the
/// largest), or infinite where it cannot be smooth (an isolated vertex; a
/// non-manifold vertex other than a crease; a one-face boundary vertex under
/// edge-and-corner interpolation).
/// \param mesh the level (its corner tags are read).
/// \param topology the topology of \p mesh.
/// \param boundary the boundary interpolation.
/// \param creasing the level's creasing (compute_creasing()).
/// \return one sharpness per vertex.
/// \throws std::bad_alloc if memory runs out.
std::vector<double> vertex_sharpness(const PolygonMesh& mesh, const MeshTopology& topology,
                                     BoundaryInterpolation boundary, const LevelCreasing& creasing);

}  // namespace subdiv
