#pragma once
/// \file
/// Quasi 4-8 refinement (L.\ Velho, "Quasi 4-8 subdivision", Algorithm 1): a
/// binary step whose topology depends on the geometry. Edges are visited
/// longest first; an edge not yet marked is split and its cluster (the edges
/// of the faces beside it, itself included) is marked; then every face with a
/// split edge is bisected through that edge's split point to the opposite
/// vertex. Marking leaves at most one split edge per face, so the bisection
/// is always through "the longest split edge" and leaves no T-junction.
///
/// The visiting order (the paper's "by decreasing length and radially around
/// each vertex", made precise here):
///   1. edges sorted by decreasing length;
///   2. lengths within a relative tolerance of each other are ties: a tie
///      class starts at the longest edge not yet classed and takes every edge
///      whose length is at least (1 - tie_tolerance) times that length;
///   3. within a class, edges are taken in radial order: vertices in
///      increasing index, the edges of each vertex counter-clockwise from its
///      ring's first edge (MeshTopology::vertex_edges), an edge at its first
///      appearance in that walk. So on a fan whose centre is vertex 0, tied
///      spokes are taken around the centre: every other one splits.
///
/// Exact ties (a regular hexagon, a regular 4-8 grid) are thus decided by the
/// vertex numbering and ring starts, deterministically; perturbed geometry by
/// the lengths alone.
///
/// Child vertices: the parent's keep their numbers [0, V); the split point of
/// the i-th split edge (split edges in increasing edge index) is V + i, placed
/// at the edge's midpoint (the smoothing operator moves it). A bisected face
/// (a, b, c) split on edge ab at s becomes (a, s, c), (s, b, c) in that order;
/// an unsplit face is copied. Child faces follow the parent faces' order.
/// Crease tags on a split edge become tags on both halves (same sharpness:
/// Velho's tags are on or off); corner tags and global options are kept.
/// Face-varying values of a split point are the average of the split edge's
/// two corner values within each bisected face.

#include <span>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"

namespace subdiv {

/// Relative length difference below which two edges tie (step 2 above).
inline constexpr double kDefaultTieTolerance = 1e-9;

/// Where a bisection step's child vertices come from.
struct BisectionMap {
  Index old_vertex_count = 0;      ///< child vertices [0, old_vertex_count) are the parent's own
  std::vector<Index> split_edges;  ///< child vertex old_vertex_count + i splits parent edge split_edges[i]
  /// The child's vertex count.
  /// \return old_vertex_count plus one per split edge.
  Index child_vertex_count() const noexcept { return old_vertex_count + static_cast<Index>(split_edges.size()); }
  /// Whether a child vertex is a split point (not one of the parent's).
  /// \param child_vertex a child vertex.
  /// \return true for child_vertex >= old_vertex_count.
  bool is_new(Index child_vertex) const noexcept { return child_vertex >= old_vertex_count; }
};

/// The order in which Algorithm 1 visits the edges: by decreasing length,
/// ties (within \p tie_tolerance) in radial order (see above).
/// \param topology the parent's topology.
/// \param positions the parent's positions, one per vertex of \p topology.
/// \param tie_tolerance the relative length difference below which edges
///   tie, in [0, 1).
/// \return every edge of \p topology once, in visiting order.
/// \pre \p positions has an entry for every vertex of \p topology (unchecked).
/// \throws std::bad_alloc if memory runs out.
std::vector<Index> bisection_edge_order(const MeshTopology& topology, std::span<const Vec3> positions,
                                        double tie_tolerance = kDefaultTieTolerance);

/// Per parent edge, whether Algorithm 1 splits it (1) or not (0): edges in
/// bisection_edge_order(), each split unless a split edge's cluster marked it.
/// \param topology the parent's topology.
/// \param positions the parent's positions, one per vertex of \p topology.
/// \param tie_tolerance the relative length difference below which edges
///   tie, in [0, 1).
/// \return one entry per edge of \p topology.
/// \pre \p positions has an entry for every vertex of \p topology (unchecked).
/// \throws std::bad_alloc if memory runs out.
std::vector<char> bisection_split_edges(const MeshTopology& topology, std::span<const Vec3> positions,
                                        double tie_tolerance = kDefaultTieTolerance);

/// One binary step on the triangle mesh `parent` (positions decide the
/// split): the child's faces, tags, face-varying channels and positions
/// (the parent's, then the split edges' midpoints). Vertex channels are left
/// for the smoothing.
/// \param parent the parent level (positions, tags, face-varying channels).
/// \param topology the topology of \p parent.
/// \param child receives the child level; its previous contents are replaced.
/// \param tie_tolerance the relative length difference below which edges
///   tie, in [0, 1).
/// \return where the child's vertices come from.
/// \pre \p topology was built from \p parent (unchecked).
/// \throws TopologyError if a face is not a triangle or repeats a vertex on
///   consecutive corners (a degenerate face).
/// \throws std::bad_alloc if memory runs out.
BisectionMap bisection_split(const PolygonMesh& parent, const MeshTopology& topology, PolygonMesh& child,
                             double tie_tolerance = kDefaultTieTolerance);

}  // namespace subdiv
