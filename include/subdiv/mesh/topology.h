#pragma once
// Connectivity derived from a PolygonMesh's face arrays: edges, edge-face
// incidence, ordered vertex rings, boundary loops. Built in O(n) after a
// per-vertex bucket sort of half-edges (buckets are as small as valences).

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv {

enum class VertexKind : std::uint8_t {
  isolated,      ///< used by no face
  interior,      ///< one closed fan of faces, every incident edge has two faces
  boundary,      ///< one open fan, bounded by two boundary edges
  non_manifold,  ///< several fans, a non-manifold incident edge, or a face using it twice
};

/// A connected component of the boundary-edge graph. When the component is a
/// simple closed chain of consistently oriented boundary edges, `vertices`
/// follows it in the faces' direction and `ordered` is true; otherwise
/// `vertices` lists the component's vertices in increasing order.
struct BoundaryLoop {
  std::vector<Index> vertices;
  bool ordered = false;
  friend bool operator==(const BoundaryLoop&, const BoundaryLoop&) = default;
};

class MeshTopology {
 public:
  /// Throws InvalidInputError if the mesh's index arrays are malformed
  /// (see check_indices). Any other defect (degenerate faces, non-manifold
  /// elements, flipped faces) is represented, not rejected.
  explicit MeshTopology(const PolygonMesh& mesh);

  /// The topology of `child`, the quad split of the mesh `parent` describes
  /// (child vertices [face points | edge points | vertex points], child face
  /// = parent corner), derived from the parent's in linear time without
  /// sorting. Identical to MeshTopology(child). Requires every parent vertex
  /// to have an ordered ring or no face; returns nullopt otherwise, and the
  /// caller builds the topology from the child's faces.
  static std::optional<MeshTopology> from_quad_split(const MeshTopology& parent, const PolygonMesh& child);
  /// The same for the triangle split of a triangle mesh (child vertices
  /// [edge points | vertex points], child faces 4f .. 4f+3).
  static std::optional<MeshTopology> from_triangle_split(const MeshTopology& parent, const PolygonMesh& child);
  /// The same for the sqrt3 split of a closed manifold triangle mesh (child
  /// vertices [face points | vertex points], child faces 2e, 2e+1 per edge);
  /// nullopt for open meshes, whose trisecting steps it does not cover.
  static std::optional<MeshTopology> from_sqrt3_split(const MeshTopology& parent, const PolygonMesh& child);
  /// The same for the sqrt2 split of a closed manifold polygon mesh (child
  /// vertices [face points | vertex points], child face e per edge).
  static std::optional<MeshTopology> from_sqrt2_split(const MeshTopology& parent, const PolygonMesh& child);

  /// True when every vertex has an ordered ring or no face at all.
  bool all_rings_ordered() const;

  friend bool operator==(const MeshTopology&, const MeshTopology&) = default;

  Index vertex_count() const { return static_cast<Index>(vertex_kind_.size()); }
  Index face_count() const { return static_cast<Index>(face_offsets_.size()) - 1; }
  Index corner_count() const { return static_cast<Index>(corner_vertex_.size()); }
  Index edge_count() const { return static_cast<Index>(edge_vertices_.size()); }

  // --- faces and corners -------------------------------------------------
  Index face_size(Index f) const {
    if (uniform_face_size_ != 0) return uniform_face_size_;  // no loads on refined levels
    return face_offsets_[f + 1] - face_offsets_[f];
  }
  Index face_first_corner(Index f) const { return face_offsets_[f]; }
  /// The vertices of face f, in order (the mesh's face f).
  std::span<const Index> face_vertices(Index f) const {
    return {corner_vertex_.data() + face_offsets_[f], static_cast<std::size_t>(face_size(f))};
  }
  Index corner_face(Index c) const {
    if (uniform_face_size_ == 4) return c / 4;  // constant divisors: no division instruction
    if (uniform_face_size_ == 3) return c / 3;
    return corner_face_[c];
  }
  Index corner_vertex(Index c) const { return corner_vertex_[c]; }
  Index corner_next(Index c) const {
    if (uniform_face_size_ == 4) return c % 4 == 3 ? c - 3 : c + 1;
    if (uniform_face_size_ == 3) return c % 3 == 2 ? c - 2 : c + 1;
    const Index f = corner_face_[c];
    return c + 1 == face_offsets_[f + 1] ? face_offsets_[f] : c + 1;
  }
  Index corner_prev(Index c) const {
    if (uniform_face_size_ == 4) return c % 4 == 0 ? c + 3 : c - 1;
    if (uniform_face_size_ == 3) return c % 3 == 0 ? c + 2 : c - 1;
    const Index f = corner_face_[c];
    return c == face_offsets_[f] ? face_offsets_[f + 1] - 1 : c - 1;
  }
  /// Edge from corner c to the next corner of its face; kInvalidIndex when
  /// both corners hold the same vertex (a degenerate face).
  Index corner_edge(Index c) const { return corner_edge_[c]; }
  /// The corner on the other side of corner c's edge (it runs the edge the
  /// other way on a consistently oriented mesh); kInvalidIndex unless the
  /// edge has exactly two sides.
  Index corner_across(Index c) const {
    const Index e = corner_edge_[c];
    if (e == kInvalidIndex || edge_face_count(e) != 2) return kInvalidIndex;
    const auto sides = edge_corners(e);
    return sides[0] == c ? sides[1] : sides[0];
  }

  // --- edges ---------------------------------------------------------------
  /// The two vertices, smaller index first.
  std::array<Index, 2> edge_vertices(Index e) const { return edge_vertices_[e]; }
  /// The corners whose outgoing edge is e: one per face side, increasing.
  std::span<const Index> edge_corners(Index e) const { return span_of(edge_corner_offsets_, edge_corners_, e); }
  Index edge_face_count(Index e) const { return edge_corner_offsets_[e + 1] - edge_corner_offsets_[e]; }
  bool is_boundary_edge(Index e) const { return edge_face_count(e) == 1; }
  bool is_non_manifold_edge(Index e) const { return edge_face_count(e) > 2; }
  /// True when the edge has two face sides traversing it in the same
  /// direction: the faces' orientations disagree.
  bool is_flipped_edge(Index e) const;
  /// The edge joining a and b, or kInvalidIndex.
  Index find_edge(Index a, Index b) const;

  // --- vertices ------------------------------------------------------------
  VertexKind vertex_kind(Index v) const { return vertex_kind_[v]; }
  /// Face corners at v. When ring_ordered(v) they run counter-clockwise
  /// around v (seen from outside); for a boundary vertex the first corner's
  /// face has vertex_edges(v).front() as a boundary edge.
  std::span<const Index> vertex_corners(Index v) const { return span_of(vertex_corner_offsets_, vertex_corners_, v); }
  /// Edges at v. When ring_ordered(v): e_0 .. e_{m-1} counter-clockwise,
  /// with face vertex_corners(v)[j] lying between e_j and e_{j+1}; a boundary
  /// vertex has m = k + 1 edges for k faces, e_0 and e_k on the boundary.
  /// Otherwise increasing edge indices.
  std::span<const Index> vertex_edges(Index v) const { return span_of(vertex_edge_offsets_, vertex_edges_, v); }
  Index valence(Index v) const { return vertex_edge_offsets_[v + 1] - vertex_edge_offsets_[v]; }
  Index vertex_face_count(Index v) const { return vertex_corner_offsets_[v + 1] - vertex_corner_offsets_[v]; }
  bool ring_ordered(Index v) const { return ring_ordered_[v] != 0; }
  /// Number of edge-connected fans of faces around v (0 for isolated).
  Index fan_count(Index v) const { return fan_count_[v]; }
  /// The vertex at the other end of edge e from v.
  Index other_vertex(Index e, Index v) const {
    return edge_vertices_[e][0] == v ? edge_vertices_[e][1] : edge_vertices_[e][0];
  }

  // --- boundary ------------------------------------------------------------
  const std::vector<BoundaryLoop>& boundary_loops() const { return boundary_loops_; }

 private:
  MeshTopology() = default;
  static std::span<const Index> span_of(const std::vector<Index>& offsets,
                                        const std::vector<Index>& items, Index i) {
    return {items.data() + offsets[i], static_cast<std::size_t>(offsets[i + 1] - offsets[i])};
  }
  void build_edges();
  void build_vertex_incidence();
  Index local_fan_count(Index v, std::vector<Index>& parent, std::vector<std::pair<Index, Index>>& seen) const;
  void classify_and_order_vertices();
  bool order_ring(Index v, std::vector<Index>& ring_corners, std::vector<Index>& ring_edges);
  void build_boundary_loops();
  // Shared by the derived constructions (topology_derived.h): turn per-vertex
  // incidence counts into offsets and storage with manifold defaults; copy
  // each vertex point's ring from its parent vertex.
  void lay_out_vertex_incidence();
  template <typename ChildCorner, typename Half>
  void inherit_vertex_points(const MeshTopology& parent, Index vertex_point, ChildCorner child_corner, Half half);
  // Shared by the sqrt3 and sqrt2 derivations: lay out the incidence of a
  // child level [face points | vertex points] whose face points have
  // `face_point_ring` corners (0: their parent face's size); write a ring
  // from its smallest corner on (the generic walk's order); and write the
  // vertex points' rings.
  void lay_out_point_split_incidence(const MeshTopology& parent, Index face_point_ring);
  void write_ring_from_smallest_corner(Index child_vertex, const Index* ring_corners, const Index* ring_edges, Index n);
  void derive_vertex_point_rings(const MeshTopology& parent, Index vertex_point, Index corners_per_edge,
                                 std::span<const Index> spoke_of);

  std::vector<Index> face_offsets_;
  std::vector<Index> corner_vertex_;
  /// 3 or 4 when every face has that many corners: then corner_face_ stays
  /// empty (face f owns corners [n f, n f + n)), which saves an array as
  /// large as the faces on every refined level. 0 otherwise.
  Index uniform_face_size_ = 0;
  std::vector<Index> corner_face_;
  std::vector<Index> corner_edge_;

  std::vector<std::array<Index, 2>> edge_vertices_;
  std::vector<Index> edge_corner_offsets_;
  std::vector<Index> edge_corners_;

  std::vector<Index> vertex_corner_offsets_;
  std::vector<Index> vertex_corners_;
  std::vector<Index> vertex_edge_offsets_;
  std::vector<Index> vertex_edges_;
  std::vector<VertexKind> vertex_kind_;
  std::vector<std::uint8_t> ring_ordered_;
  std::vector<Index> fan_count_;

  std::vector<BoundaryLoop> boundary_loops_;
};

}  // namespace subdiv
