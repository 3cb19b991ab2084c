#pragma once
/// \file
/// Connectivity derived from a PolygonMesh's face arrays: edges, edge-face
/// incidence, ordered vertex rings, boundary loops. Built in O(n) after a
/// per-vertex bucket sort of half-edges (buckets are as small as valences).

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv {

/// How the faces around a vertex fit together.
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
  std::vector<Index> vertices;  ///< the component's vertices (the first is not repeated at the end)
  bool ordered = false;         ///< whether `vertices` runs along a simple oriented loop
  /// Member-wise equality.
  /// \param a first loop.
  /// \param b second loop.
  /// \return whether the vertices and the ordered flag are equal.
  friend bool operator==(const BoundaryLoop& a, const BoundaryLoop& b) = default;
};

/// Connectivity of a PolygonMesh: edges (numbered in increasing (min, max)
/// vertex order), edge-face incidence, per-vertex corners and edges (ordered
/// counter-clockwise where the vertex's faces allow it), fans and boundary
/// loops. Immutable once built; it does not refer to the mesh it was built
/// from. Accessors taking an element index do not check it: the index must
/// lie in the element's range.
class MeshTopology {
 public:
  /// Builds the topology of \p mesh's faces in O(n) (n: corners plus
  /// vertices). Any defect other than malformed face arrays (degenerate
  /// faces, non-manifold elements, flipped faces) is represented, not
  /// rejected. Channels, polylines and tags are not read.
  /// \param mesh the mesh.
  /// \throws InvalidInputError if the mesh's face arrays are malformed
  ///         (see check_face_arrays()).
  /// \throws std::bad_alloc if memory runs out.
  explicit MeshTopology(const PolygonMesh& mesh);
  /// The same, with the edges' identity given: two face sides are one edge
  /// when they join the same two vertices and their corners have the same
  /// key. A refined level whose parent had coincident edges (see
  /// has_coincident_edges()) is built this way, so that edges that are
  /// distinct in the hierarchy stay distinct when they join the same two
  /// vertices. Sides joining a vertex to itself are edges of their own.
  /// \param mesh the mesh.
  /// \param corner_edge_key a key per face corner, for the side from that
  ///        corner to the next.
  /// \throws InvalidInputError if the mesh's face arrays are malformed, or
  ///         if the keys are not one per corner.
  /// \throws std::bad_alloc if memory runs out.
  MeshTopology(const PolygonMesh& mesh, std::span<const Index> corner_edge_key);

  /// The topology of `child`, the quad split of the mesh `parent` describes
  /// (child vertices [face points | edge points | vertex points], child face
  /// = parent corner), derived from the parent's in linear time without
  /// sorting. Identical to MeshTopology(child). Requires every parent vertex
  /// to have an ordered ring or no face; returns nullopt otherwise, and the
  /// caller builds the topology from the child's faces.
  /// \pre \p child is the quad split of \p parent's mesh in that numbering (not checked).
  /// \param parent the parent level's topology.
  /// \param child the child level's mesh.
  /// \return the child's topology, or nullopt when the parent does not qualify.
  /// \throws std::bad_alloc if memory runs out.
  static std::optional<MeshTopology> from_quad_split(const MeshTopology& parent, const PolygonMesh& child);
  /// The same for the triangle split of a triangle mesh (child vertices
  /// [edge points | vertex points], child faces 4f .. 4f+3); nullopt also
  /// when a parent face is not a triangle or two faces share all three
  /// vertices.
  /// \pre \p child is the triangle split of \p parent's mesh in that numbering (not checked).
  /// \param parent the parent level's topology.
  /// \param child the child level's mesh.
  /// \return the child's topology, or nullopt when the parent does not qualify.
  /// \throws std::bad_alloc if memory runs out.
  static std::optional<MeshTopology> from_triangle_split(const MeshTopology& parent, const PolygonMesh& child);
  /// The same for the sqrt3 split of a closed manifold triangle mesh (child
  /// vertices [face points | vertex points], child faces 2e, 2e+1 per edge);
  /// nullopt for open meshes, whose trisecting steps it does not cover, and
  /// for meshes the fast derivation does not handle (repeated corner
  /// vertices, a face adjacent to itself or twice to another).
  /// \pre \p child is the sqrt3 split of \p parent's mesh in that numbering
  ///      (only its vertex and face counts are checked).
  /// \param parent the parent level's topology.
  /// \param child the child level's mesh.
  /// \return the child's topology, or nullopt when the parent does not qualify.
  /// \throws std::bad_alloc if memory runs out.
  static std::optional<MeshTopology> from_sqrt3_split(const MeshTopology& parent, const PolygonMesh& child);
  /// The same for the sqrt2 split of a closed manifold polygon mesh (child
  /// vertices [face points | vertex points], child face e per edge); nullopt
  /// otherwise, and for faces with a repeated vertex.
  /// \pre \p child is the sqrt2 split of \p parent's mesh in that numbering
  ///      (only its vertex and face counts are checked).
  /// \param parent the parent level's topology.
  /// \param child the child level's mesh.
  /// \return the child's topology, or nullopt when the parent does not qualify.
  /// \throws std::bad_alloc if memory runs out.
  static std::optional<MeshTopology> from_sqrt2_split(const MeshTopology& parent, const PolygonMesh& child);

  /// Whether the derived constructions (from_quad_split() ...) can start
  /// from this topology. O(vertices).
  /// \return true when every vertex has an ordered ring or no face at all.
  bool all_rings_ordered() const noexcept;

  /// Equality of every array (the same faces give equal topologies).
  /// \param a first topology.
  /// \param b second topology.
  /// \return whether the two describe the same connectivity, numbered alike.
  friend bool operator==(const MeshTopology& a, const MeshTopology& b) = default;

  /// \return the number of vertices (the mesh's vertex_count(), isolated ones included).
  Index vertex_count() const noexcept { return static_cast<Index>(vertex_kind_.size()); }
  /// \return the number of faces.
  Index face_count() const noexcept { return static_cast<Index>(face_offsets_.size()) - 1; }
  /// \return the number of face corners over all faces.
  Index corner_count() const noexcept { return static_cast<Index>(corner_vertex_.size()); }
  /// \return the number of edges (see edge_vertices() for which face sides share one).
  Index edge_count() const noexcept { return static_cast<Index>(edge_vertices_.size()); }
  /// Whether two edges join the same two vertices, or an edge joins a
  /// vertex to itself. Built from faces alone, face sides joining the same
  /// two vertices are one edge, as in OpenSubdiv, except that a side joining
  /// a vertex to itself (a face repeating a vertex on consecutive corners) is
  /// an edge of its own, and so is a face's second side along an edge that
  /// the same face already runs along last (a face visiting it twice).
  /// \return true when find_edge() does not identify every edge.
  bool has_coincident_edges() const noexcept { return coincident_edges_; }
  /// Whether the edges' identity was given (the keyed constructor): then
  /// coincident edges are distinct edges of a refined level, not defects of
  /// the input.
  /// \return true when built with edge keys.
  bool edges_keyed() const noexcept { return edges_keyed_; }
  /// Whether vertex \p v is an end of an edge joining a vertex to itself or
  /// of two edges joining the same two vertices. O(valence^2).
  /// \pre 0 <= v < vertex_count().
  /// \param v the vertex.
  /// \return true when one of its edges is such an edge.
  bool on_coincident_edge(Index v) const noexcept;
  /// OpenSubdiv's sharpening of non-manifold vertices on its base level
  /// (Far::TopologyRefinerFactoryBase::prepareComponentTagsAndSharpness): a
  /// non-manifold vertex (an unordered ring, or an end of the input's
  /// coincident edges) becomes an infinitely sharp corner unless it lies on
  /// an interior non-manifold crease: exactly two of its edges non-manifold
  /// (more than two faces, flipped, joining the vertex to itself, or
  /// coincident with another), none on the boundary, and more faces than
  /// edges around it. O(valence).
  /// \pre 0 <= v < vertex_count().
  /// \param v the vertex.
  /// \return whether the control mesh's vertex \p v is made a corner.
  bool is_non_manifold_corner(Index v) const noexcept;

  // --- faces and corners -------------------------------------------------
  /// Number of corners of face \p f.
  /// \pre 0 <= f < face_count().
  /// \param f the face.
  /// \return the face's size.
  Index face_size(Index f) const noexcept {
    if (uniform_face_size_ != 0) return uniform_face_size_;  // no loads on refined levels
    return face_offsets_[f + 1] - face_offsets_[f];
  }
  /// The corner index of face \p f's first corner; its corners are
  /// face_first_corner(f) .. face_first_corner(f) + face_size(f) - 1.
  /// \pre 0 <= f <= face_count() (f == face_count() gives corner_count()).
  /// \param f the face.
  /// \return the first corner's index.
  Index face_first_corner(Index f) const noexcept { return face_offsets_[f]; }
  /// The vertices of face \p f, in order (the mesh's face f).
  /// \pre 0 <= f < face_count().
  /// \param f the face.
  /// \return a view into the topology, valid as long as it lives.
  std::span<const Index> face_vertices(Index f) const noexcept {
    return {corner_vertex_.data() + face_offsets_[f], static_cast<std::size_t>(face_size(f))};
  }
  /// The face corner \p c belongs to.
  /// \pre 0 <= c < corner_count().
  /// \param c the corner.
  /// \return the face's index.
  Index corner_face(Index c) const noexcept {
    if (uniform_face_size_ == 4) return c / 4;  // constant divisors: no division instruction
    if (uniform_face_size_ == 3) return c / 3;
    return corner_face_[c];
  }
  /// The vertex at corner \p c.
  /// \pre 0 <= c < corner_count().
  /// \param c the corner.
  /// \return the vertex's index.
  Index corner_vertex(Index c) const noexcept { return corner_vertex_[c]; }
  /// The next corner of \p c's face (counter-clockwise), wrapping from the
  /// last corner to the first.
  /// \pre 0 <= c < corner_count().
  /// \param c the corner.
  /// \return the next corner's index.
  Index corner_next(Index c) const noexcept {
    if (uniform_face_size_ == 4) return c % 4 == 3 ? c - 3 : c + 1;
    if (uniform_face_size_ == 3) return c % 3 == 2 ? c - 2 : c + 1;
    const Index f = corner_face_[c];
    return c + 1 == face_offsets_[f + 1] ? face_offsets_[f] : c + 1;
  }
  /// The previous corner of \p c's face, wrapping from the first corner to
  /// the last.
  /// \pre 0 <= c < corner_count().
  /// \param c the corner.
  /// \return the previous corner's index.
  Index corner_prev(Index c) const noexcept {
    if (uniform_face_size_ == 4) return c % 4 == 0 ? c + 3 : c - 1;
    if (uniform_face_size_ == 3) return c % 3 == 0 ? c + 2 : c - 1;
    const Index f = corner_face_[c];
    return c == face_offsets_[f] ? face_offsets_[f + 1] - 1 : c - 1;
  }
  /// The edge from corner \p c to the next corner of its face.
  /// \pre 0 <= c < corner_count().
  /// \param c the corner.
  /// \return the edge's index (an edge of its own, joining the vertex to
  ///         itself, when both corners hold the same vertex).
  Index corner_edge(Index c) const noexcept { return corner_edge_[c]; }
  /// The corner on the other side of corner \p c's edge (it runs the edge the
  /// other way on a consistently oriented mesh).
  /// \pre 0 <= c < corner_count().
  /// \param c the corner.
  /// \return the other side's corner; kInvalidIndex unless the edge has
  ///         exactly two sides.
  Index corner_across(Index c) const noexcept {
    const Index e = corner_edge_[c];
    if (e == kInvalidIndex || edge_face_count(e) != 2) return kInvalidIndex;
    const auto sides = edge_corners(e);
    return sides[0] == c ? sides[1] : sides[0];
  }

  // --- edges ---------------------------------------------------------------
  /// The two vertices of edge \p e.
  /// \pre 0 <= e < edge_count().
  /// \param e the edge.
  /// \return the two vertices, smaller index first (equal for an edge
  ///         joining a vertex to itself).
  std::array<Index, 2> edge_vertices(Index e) const noexcept { return edge_vertices_[e]; }
  /// The corners whose outgoing edge is \p e: one per face side.
  /// \pre 0 <= e < edge_count().
  /// \param e the edge.
  /// \return the corners in increasing order; a view into the topology,
  ///         valid as long as it lives.
  std::span<const Index> edge_corners(Index e) const noexcept { return span_of(edge_corner_offsets_, edge_corners_, e); }
  /// Number of face sides along edge \p e (a face using the edge twice counts twice).
  /// \pre 0 <= e < edge_count().
  /// \param e the edge.
  /// \return edge_corners(e).size().
  Index edge_face_count(Index e) const noexcept { return edge_corner_offsets_[e + 1] - edge_corner_offsets_[e]; }
  /// Whether edge \p e is on the boundary.
  /// \pre 0 <= e < edge_count().
  /// \param e the edge.
  /// \return true when the edge has exactly one face side.
  bool is_boundary_edge(Index e) const noexcept { return edge_face_count(e) == 1; }
  /// Whether edge \p e is non-manifold.
  /// \pre 0 <= e < edge_count().
  /// \param e the edge.
  /// \return true when the edge has more than two face sides.
  bool is_non_manifold_edge(Index e) const noexcept { return edge_face_count(e) > 2; }
  /// Whether the faces along edge \p e disagree on orientation.
  /// \pre 0 <= e < edge_count().
  /// \param e the edge.
  /// \return true when the edge has two face sides traversing it in the
  ///         same direction; false for any other number of sides.
  bool is_flipped_edge(Index e) const noexcept;
  /// The edge joining \p a and \p b, by binary search (O(log E)).
  /// \param a one vertex; any value.
  /// \param b the other vertex, in either order; any value.
  /// \return the edge's index (the first of coincident edges), or
  ///         kInvalidIndex when there is no such edge (including
  ///         out-of-range vertices and a == b).
  Index find_edge(Index a, Index b) const noexcept;

  // --- vertices ------------------------------------------------------------
  /// How the faces around vertex \p v fit together.
  /// \pre 0 <= v < vertex_count().
  /// \param v the vertex.
  /// \return the vertex's kind.
  VertexKind vertex_kind(Index v) const noexcept { return vertex_kind_[v]; }
  /// Face corners at v. When ring_ordered(v) they run counter-clockwise
  /// around v (seen from outside); for a boundary vertex the first corner's
  /// face has vertex_edges(v).front() as a boundary edge.
  /// \pre 0 <= v < vertex_count().
  /// \param v the vertex.
  /// \return every face corner whose vertex is \p v; a view into the
  ///         topology, valid as long as it lives.
  std::span<const Index> vertex_corners(Index v) const noexcept { return span_of(vertex_corner_offsets_, vertex_corners_, v); }
  /// Edges at v. When ring_ordered(v): e_0 .. e_{m-1} counter-clockwise,
  /// with face vertex_corners(v)[j] lying between e_j and e_{j+1}; a boundary
  /// vertex has m = k + 1 edges for k faces, e_0 and e_k on the boundary.
  /// Otherwise increasing edge indices.
  /// \pre 0 <= v < vertex_count().
  /// \param v the vertex.
  /// \return the edges at \p v (an edge joining v to itself twice, as
  ///         OpenSubdiv lists it); a view into the topology, valid as long
  ///         as it lives.
  std::span<const Index> vertex_edges(Index v) const noexcept { return span_of(vertex_edge_offsets_, vertex_edges_, v); }
  /// Number of edges at vertex \p v (an edge joining v to itself counts twice).
  /// \pre 0 <= v < vertex_count().
  /// \param v the vertex.
  /// \return vertex_edges(v).size().
  Index valence(Index v) const noexcept { return vertex_edge_offsets_[v + 1] - vertex_edge_offsets_[v]; }
  /// Number of face corners at vertex \p v (a face using it twice counts twice).
  /// \pre 0 <= v < vertex_count().
  /// \param v the vertex.
  /// \return vertex_corners(v).size().
  Index vertex_face_count(Index v) const noexcept { return vertex_corner_offsets_[v + 1] - vertex_corner_offsets_[v]; }
  /// Whether vertex \p v's corners and edges are in ring order (see
  /// vertex_corners() and vertex_edges()). Only interior and boundary
  /// vertices can be, and only when their faces are consistently oriented
  /// around them.
  /// \pre 0 <= v < vertex_count().
  /// \param v the vertex.
  /// \return whether the ring is ordered; false for isolated vertices.
  bool ring_ordered(Index v) const noexcept { return ring_ordered_[v] != 0; }
  /// Number of edge-connected fans of faces around v (0 for isolated).
  /// \pre 0 <= v < vertex_count().
  /// \param v the vertex.
  /// \return the number of fans.
  Index fan_count(Index v) const noexcept { return fan_count_[v]; }
  /// The vertex at the other end of edge e from v.
  /// \pre 0 <= e < edge_count() and \p v is one of the edge's vertices
  ///      (otherwise the edge's first vertex is returned).
  /// \param e the edge.
  /// \param v one of its vertices.
  /// \return the edge's other vertex.
  Index other_vertex(Index e, Index v) const noexcept {
    return edge_vertices_[e][0] == v ? edge_vertices_[e][1] : edge_vertices_[e][0];
  }

  // --- boundary ------------------------------------------------------------
  /// The components of the boundary-edge graph, in increasing order of their
  /// smallest vertex; an ordered loop starts at its smallest vertex.
  /// \return one BoundaryLoop per component (none for a closed mesh); valid
  ///         as long as the topology lives.
  const std::vector<BoundaryLoop>& boundary_loops() const noexcept { return boundary_loops_; }

 private:
  MeshTopology() = default;
  static std::span<const Index> span_of(const std::vector<Index>& offsets,
                                        const std::vector<Index>& items, Index i) {
    return {items.data() + offsets[i], static_cast<std::size_t>(offsets[i + 1] - offsets[i])};
  }
  void build_edges(std::span<const Index> corner_edge_key);
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
  bool coincident_edges_ = false;
  bool edges_keyed_ = false;
};

}  // namespace subdiv
