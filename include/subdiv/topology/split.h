#pragma once
// Topology refinement rules (Zorin's survey, section 3.1): how a level's
// faces are split into the next level's, independent of any scheme.
//
//   quad split (QP, arity 2): every n-gon -> n quads around a new face point;
//     child vertices are numbered [face points | edge points | vertex points].
//   triangle split (TP, arity 2): every triangle -> 4 triangles;
//     child vertices are numbered [edge points | vertex points].
//   dual split (QD, arity 2, Doo-Sabin): a child vertex per face corner, and
//     a face per parent face, edge and vertex; child vertices are numbered
//     [corner points | boundary points, two per boundary edge]
//     (src/topology/dual_split.cpp).
//   midedge split (QD, arity sqrt 2): a child vertex per edge, a face per
//     parent face and vertex; child vertices are numbered as the edges
//     (src/topology/midedge_split.cpp). Closed meshes only.
//   identity: the same faces and vertices (a smoothing step of a composite
//     scheme, e.g. B_{alpha,beta} of generalized Catmull-Clark); child
//     vertices are numbered as the parent's (vertex points).
//   quasi 4-8 bisection (arity sqrt 2, Velho): a binary step whose split
//     depends on the parent's positions (subdiv/topology/bisection_split.h);
//     child vertices are numbered [vertex points | split points, one per
//     split edge].
//   sqrt3 split (TP, arity sqrt 3, Kobbelt): a face point per triangle, the
//     old edges flipped; boundary edges kept on odd steps and trisected on
//     even ones; child vertices are numbered [face points | boundary points,
//     two per boundary edge on even steps | vertex points]
//     (src/topology/sqrt3_split.cpp).
//   sqrt2 split (QP, arity sqrt 2, 4-8 on quads): a face point per face, a
//     quad per edge, the old edges dropped; child vertices are numbered
//     [face points | vertex points] (src/topology/sqrt2_split.cpp).
//
// The child is a complete PolygonMesh (faces, tags, face-varying indices);
// its positions and vertex channels are left for a scheme's masks to fill.

#include <span>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"

namespace subdiv {

enum class SplitRule { quad, triangle, dual, midedge, identity, quasi_4_8, sqrt3, sqrt2 };

/// The primal splits keep the parent's vertices (as vertex points) and its
/// sharp features; the analysis' vertex configurations, limit positions,
/// depth and adaptive refinement are written for them.
constexpr bool is_primal(SplitRule r) { return r == SplitRule::quad || r == SplitRule::triangle; }

/// Whether a split's steps differ with the level they start from (the sqrt3
/// split's boundary treatment alternates), so that a refined mesh's level
/// is part of its state.
constexpr bool steps_alternate(SplitRule r) { return r == SplitRule::sqrt3; }

/// Whether the sqrt3 split's step from level `level` (0 = the control mesh)
/// trisects the boundary edges: every second step, the first one does not.
bool sqrt3_step_trisects(int level);

/// How much one step shrinks the faces' size: 2, sqrt 2 for the midedge and
/// sqrt2 splits and the quasi 4-8 bisection, sqrt 3 for the sqrt3 split, 1
/// for the identity.
double arity(SplitRule r);

const char* to_string(SplitRule);

/// Where a level's child vertices come from. Child vertex numbers are
/// contiguous ranges per kind of parent element.
struct SplitMap {
  SplitRule rule = SplitRule::quad;
  Index face_points = 0;    ///< first child vertex made from a parent face (quad split)
  Index edge_points = 0;    ///< first child vertex made from a parent edge
  Index vertex_points = 0;  ///< first child vertex made from a parent vertex
  Index child_vertex_count = 0;
  /// Dual split: the child vertex of parent corner c is corner_points + c;
  /// edge_points starts the boundary points, two per edge of
  /// `boundary_edges` (the one near edge_vertices(e)[0] first), and
  /// vertex_points == child_vertex_count (no vertex points).
  Index corner_points = 0;
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
  Index point_face(Index i) const { return point_faces.empty() ? i : point_faces[static_cast<std::size_t>(i)]; }

  Index face_point(Index f) const { return face_points + f; }
  Index edge_point(Index e) const { return edge_points + e; }
  Index vertex_point(Index v) const { return vertex_points + v; }
  Index corner_point(Index c) const { return corner_points + c; }
};

/// Dual split: whether parent vertex v gets a V-face (its corner points
/// around it, the boundary points of its boundary edges added). Every vertex
/// with faces does, except an interior vertex with fewer than 3, whose 2-gon
/// its E-faces already close. V-faces are numbered in vertex order among
/// these vertices, after the F- and E-faces.
bool dual_split_has_v_face(const MeshTopology& topology, Index v);

/// The child faces of parent face f, [first, last): the quad split makes one
/// per corner (child face = parent corner), the triangle split 4f .. 4f+3,
/// the dual and midedge splits one (child face f, its F-face). The sqrt3
/// and sqrt2 splits' child faces belong to edges, not faces: throws
/// InvalidInputError.
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
/// Requires every face corner to have an edge (no degenerate faces) and, for
/// the triangle, sqrt3 and bisection splits, triangles only; throws
/// TopologyError otherwise.
SplitMap split_topology(const PolygonMesh& parent, const MeshTopology& topology, SplitRule rule,
                        PolygonMesh& child, const SplitOptions& options = {});

}  // namespace subdiv
