#pragma once
/// \file
/// Topology refinement rules (Zorin's survey, section 3.1): how a level's
/// faces are split into the next level's, independent of any scheme.
///
/// - quad split (QP, arity 2): every n-gon -> n quads around a new face point;
///   child vertices are numbered [face points | edge points | vertex points].
/// - triangle split (TP, arity 2): every triangle -> 4 triangles;
///   child vertices are numbered [edge points | vertex points].
/// - dual split (QD, arity 2, Doo-Sabin): a child vertex per face corner, and
///   a face per parent face, edge and vertex; child vertices are numbered
///   [corner points | boundary points, two per boundary edge]
///   (src/topology/dual_split.cpp).
/// - midedge split (QD, arity sqrt 2): a child vertex per edge, a face per
///   parent face and vertex; child vertices are numbered as the edges
///   (src/topology/midedge_split.cpp). Schemes on it take closed meshes only.
/// - identity: the same faces and vertices (a smoothing step of a composite
///   scheme, e.g. B_{alpha,beta} of generalized Catmull-Clark); child
///   vertices are numbered as the parent's (vertex points).
/// - quasi 4-8 bisection (arity sqrt 2, Velho): a binary step whose split
///   depends on the parent's positions (subdiv/topology/bisection_split.h);
///   child vertices are numbered [vertex points | split points, one per
///   split edge].
/// - sqrt3 split (TP, arity sqrt 3, Kobbelt): a face point per triangle, the
///   old edges flipped; boundary edges kept on odd steps and trisected on
///   even ones; child vertices are numbered [face points | boundary points,
///   two per boundary edge on even steps | vertex points]
///   (src/topology/sqrt3_split.cpp).
/// - sqrt2 split (QP, arity sqrt 2, 4-8 on quads): a face point per face, a
///   quad per edge, the old edges dropped; child vertices are numbered
///   [face points | vertex points] (src/topology/sqrt2_split.cpp).
///
/// The child is a complete PolygonMesh (faces, tags, face-varying indices);
/// its positions and vertex channels are left for a scheme's masks to fill.

#include <span>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"

namespace subdiv {

/// How a level's faces are split into the next level's (this file's
/// description details each split).
enum class SplitRule {
  quad,       ///< every n-gon into n quads (QP, arity 2)
  triangle,   ///< every triangle into 4 (TP, arity 2)
  dual,       ///< Doo-Sabin's dual split (QD, arity 2)
  midedge,    ///< a child vertex per edge (QD, arity sqrt 2)
  identity,   ///< the same faces and vertices (a composite scheme's smoothing step)
  quasi_4_8,  ///< Velho's geometric bisection (arity sqrt 2)
  sqrt3,      ///< Kobbelt's sqrt3 split (TP, arity sqrt 3)
  sqrt2,      ///< the 4-8 split of quads (QP, arity sqrt 2)
};

/// The primal splits keep the parent's vertices (as vertex points) and its
/// sharp features; the analysis' vertex configurations, limit positions,
/// depth and adaptive refinement are written for them.
/// \param r the split.
/// \return true for the quad and triangle splits.
constexpr bool is_primal(SplitRule r) noexcept { return r == SplitRule::quad || r == SplitRule::triangle; }

/// Whether a split's steps differ with the level they start from (the sqrt3
/// split's boundary treatment alternates), so that a refined mesh's level
/// is part of its state.
/// \param r the split.
/// \return true for the sqrt3 split.
constexpr bool steps_alternate(SplitRule r) noexcept { return r == SplitRule::sqrt3; }

/// Whether the sqrt3 split's step from level `level` (0 = the control mesh)
/// trisects the boundary edges: every second step, the first one does not.
/// \param level the parent's level, >= 0.
/// \return true for odd \p level.
bool sqrt3_step_trisects(int level) noexcept;

/// How much one step shrinks the faces' size: 2, sqrt 2 for the midedge and
/// sqrt2 splits and the quasi 4-8 bisection, sqrt 3 for the sqrt3 split, 1
/// for the identity.
/// \param r the split.
/// \return the arity.
double arity(SplitRule r) noexcept;

/// The split's name and class, such as "quad split (QP, arity 2)".
/// \param rule the split.
/// \return a static string ("?" for a value outside the enumeration).
const char* to_string(SplitRule rule) noexcept;

/// Where a level's child vertices come from. Child vertex numbers are
/// contiguous ranges per kind of parent element.
struct SplitMap {
  SplitRule rule = SplitRule::quad;  ///< the split that made the level
  Index face_points = 0;    ///< first child vertex made from a parent face (quad split)
  Index edge_points = 0;    ///< first child vertex made from a parent edge
  Index vertex_points = 0;  ///< first child vertex made from a parent vertex
  Index child_vertex_count = 0;  ///< the child's vertex count
  /// Dual split: the child vertex of parent corner c is corner_points + c;
  /// edge_points starts the boundary points, two per edge of
  /// `boundary_edges` (the one near edge_vertices(e)[0] first), and
  /// vertex_points == child_vertex_count (no vertex points).
  Index corner_points = 0;
  /// Dual split, and the sqrt3 split's trisecting steps: the parent's
  /// boundary edges in increasing order, two boundary points each.
  std::vector<Index> boundary_edges;
  /// Sqrt3 split: the parent face of each face point (face point i is made
  /// from face point_faces[i]); empty when every face has one (face point f
  /// is face f). On trisecting steps edge_points starts the boundary points,
  /// two per edge of `boundary_edges` as in the dual split.
  std::vector<Index> point_faces;
  /// Quasi 4-8 bisection: vertex_points is 0, and edge_points starts the
  /// split points, one per edge of `split_edges` (edge_point() does not
  /// apply: only these edges are split).
  std::vector<Index> split_edges;

  /// The parent face of face point i (i < edge_points - face_points).
  /// \param i the face point's rank among the face points.
  /// \return the parent face it is made from.
  /// \pre \p i is in [0, point_faces.size()) where point_faces is not empty
  ///   (unchecked).
  Index point_face(Index i) const noexcept {
    return point_faces.empty() ? i : point_faces[static_cast<std::size_t>(i)];
  }

  /// The child vertex made from parent face \p f (quad, sqrt2 and, where
  /// every face has one, sqrt3 splits).
  /// \param f a parent face.
  /// \return face_points + f.
  Index face_point(Index f) const noexcept { return face_points + f; }
  /// The child vertex made from parent edge \p e (quad and triangle splits;
  /// the midedge split's child vertex of \p e).
  /// \param e a parent edge.
  /// \return edge_points + e.
  Index edge_point(Index e) const noexcept { return edge_points + e; }
  /// The child vertex made from parent vertex \p v (splits with vertex points).
  /// \param v a parent vertex.
  /// \return vertex_points + v.
  Index vertex_point(Index v) const noexcept { return vertex_points + v; }
  /// The child vertex of parent face corner \p c (dual split).
  /// \param c a parent corner.
  /// \return corner_points + c.
  Index corner_point(Index c) const noexcept { return corner_points + c; }
};

/// Dual split: whether parent vertex v gets a V-face (its corner points
/// around it, the boundary points of its boundary edges added). Every vertex
/// with faces does, except an interior vertex with fewer than 3, whose 2-gon
/// its E-faces already close. V-faces are numbered in vertex order among
/// these vertices, after the F- and E-faces.
/// \param topology the parent's topology.
/// \param v a parent vertex.
/// \return true where \p v has faces and is a boundary vertex or has at
///   least 3 faces.
/// \pre \p v is in [0, topology.vertex_count()) (unchecked).
bool dual_split_has_v_face(const MeshTopology& topology, Index v) noexcept;

/// The child faces of parent face f, [first, last): the quad split makes one
/// per corner (child face = parent corner), the triangle split 4f .. 4f+3,
/// the dual, midedge and identity splits one (child face f, its F-face).
/// The sqrt3 and sqrt2 splits' child faces belong to edges, not faces.
/// \param parent the parent's topology.
/// \param rule the split.
/// \param f a parent face.
/// \return the half-open range of child faces.
/// \pre \p f is in [0, parent.face_count()) (unchecked). The quasi 4-8
///   bisection is not covered (its child faces depend on the split edges):
///   the result is then meaningless.
/// \throws InvalidInputError for the sqrt3 and sqrt2 splits.
std::pair<Index, Index> child_faces(const MeshTopology& parent, SplitRule rule, Index f);

/// What a split reads besides the parent's topology and tags.
struct SplitOptions {
  /// Chaikin creasing (LevelCreasing::child_edge_sharpness: 2e + i for the
  /// child at topology.edge_vertices(e)[i]): each half of a semi-sharp crease
  /// gets its own child sharpness instead of the tag's minus one (a half
  /// that is still infinitely sharp, an edge sharp for being a boundary,
  /// keeps the tag's minus one). Empty: the tag's minus one.
  std::span<const double> child_end_sharpness = {};
  /// The parent's level (0 = the control mesh): the sqrt3 split alternates
  /// its boundary treatment with it (sqrt3_step_trisects()).
  int level = 0;
  /// The boundary interpolation the level is refined with (the mesh's tag
  /// or an override). Under edge-and-corner, the sqrt3 split tags the vertex
  /// point of each boundary vertex with one face as an infinitely sharp
  /// corner: the split gives it two faces, and it stays a corner.
  BoundaryInterpolation boundary = BoundaryInterpolation::edge_only;
};

/// The child level's faces, tags (crease and corner sharpness decremented by
/// one per level unless infinite, holes inherited; tags no module interprets,
/// such as hierarchical edits, dropped) and face-varying channels
/// (linearly interpolated within each face). `child.positions` is resized to
/// the child vertex count and zero-filled; vertex channels are not created.
/// The parent's faces are read from `topology` only (the parent mesh gives
/// tags and face-varying channels).
/// The quasi 4-8 bisection reads the parent's positions to choose its
/// edges, and places the split points at their edges' midpoints.
/// Faces repeating a vertex on consecutive corners (an edge joining the
/// vertex to itself) are split by the quad and triangle splits only; the
/// triangle, sqrt3 and bisection splits need triangles, and the dual,
/// midedge, sqrt3 and sqrt2 splits a manifold mesh. On the control mesh
/// (options.level 0) the quad and triangle splits tag the vertex points of
/// MeshTopology::is_non_manifold_corner() vertices as corners.
/// \param parent the parent level (tags, face-varying channels; positions
///   for the quasi 4-8 bisection).
/// \param topology the topology of \p parent.
/// \param rule the split.
/// \param child receives the child level's faces, tags and face-varying
///   channels; its vertex channels are cleared.
/// \param options Chaikin child sharpness, the parent's level and the
///   boundary interpolation (the quasi 4-8 bisection reads none of them and
///   uses kDefaultTieTolerance).
/// \return where the child's vertices come from.
/// \pre \p topology was built from \p parent (unchecked).
/// \throws TopologyError for a degenerate face (other splits than the quad
///   and triangle splits), a face that is not a triangle
///   (triangle, sqrt3 and bisection splits), a non-manifold vertex (dual and
///   midedge splits) or edge (sqrt3 and sqrt2 splits), or a triangle with two
///   boundary edges on a trisecting sqrt3 step.
/// \throws std::bad_alloc if memory runs out.
SplitMap split_topology(const PolygonMesh& parent, const MeshTopology& topology, SplitRule rule,
                        PolygonMesh& child, const SplitOptions& options = {});

}  // namespace subdiv
