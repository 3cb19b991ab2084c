// Dual split (QD, arity 2), Doo and Sabin's refinement: every corner of every
// face becomes a child vertex, and the child faces are
//   F-faces: one per parent face, its corners' points in the face's order;
//   E-faces: one per edge, the quad of the four corner points at its ends
//     (two of them, on a boundary edge, are its boundary points below);
//   V-faces: one per vertex, the corner points around it in ring order
//     (a boundary vertex adds the boundary points of its two boundary edges).
// Boundaries follow Doo's construction, replicating each boundary edge into a
// degenerate quad outside it, with the degenerate elements left out: every
// boundary edge (a, b) gets two child vertices, its boundary points near a and
// near b, joined by a child boundary edge. The child's boundary is then made
// of boundary points only, so the boundary curve refines on its own.
//
// Child vertices are numbered [corner points (= parent corner) | boundary
// points (2 per boundary edge, SplitMap::boundary_edges order, the point near
// edge_vertices(e)[0] first)]. Child faces: [F-faces | E-faces of the edges,
// in edge order | V-faces of the vertices that have faces, in vertex order].
// Every face keeps the parent's orientation (checked in split_test.cpp).

#include <algorithm>

#include "split_detail.h"
#include "subdiv/core/error.h"

namespace subdiv::detail {

SplitMap dual_split(const MeshTopology& topo, PolygonMesh& child) {
  for (Index v = 0; v < topo.vertex_count(); ++v)
    if (topo.vertex_kind(v) == VertexKind::non_manifold || (topo.vertex_face_count(v) > 0 && !topo.ring_ordered(v)))
      throw TopologyError("the dual split needs a manifold mesh, but vertex " + std::to_string(v) +
                          " is non-manifold");
  SplitMap map;
  map.rule = SplitRule::dual;
  const Index nc = topo.corner_count(), ne = topo.edge_count(), nv = topo.vertex_count(), nf = topo.face_count();
  std::vector<Index> boundary_rank(static_cast<std::size_t>(ne), kInvalidIndex);
  for (Index e = 0; e < ne; ++e)
    if (topo.is_boundary_edge(e)) {
      boundary_rank[static_cast<std::size_t>(e)] = static_cast<Index>(map.boundary_edges.size());
      map.boundary_edges.push_back(e);
    }
  map.corner_points = 0;
  map.edge_points = nc;  // the boundary points
  map.vertex_points = nc + 2 * static_cast<Index>(map.boundary_edges.size());
  map.child_vertex_count = map.vertex_points;
  // The boundary point of boundary edge e near its end v.
  auto boundary_point = [&](Index e, Index v) {
    return map.edge_points + 2 * boundary_rank[static_cast<std::size_t>(e)] + (topo.edge_vertices(e)[0] == v ? 0 : 1);
  };

  child.positions.assign(static_cast<std::size_t>(map.child_vertex_count), Vec3{});
  child.face_offsets.assign(1, 0);
  child.face_indices.clear();
  child.face_indices.reserve(static_cast<std::size_t>(3 * nc + 4 * ne));
  auto close_face = [&] { child.face_offsets.push_back(static_cast<Index>(child.face_indices.size())); };

  for (Index f = 0; f < nf; ++f) {
    const Index first = topo.face_first_corner(f);
    for (Index c = first; c < first + topo.face_size(f); ++c) child.face_indices.push_back(c);
    close_face();
  }
  for (Index e = 0; e < ne; ++e) {
    const auto sides = topo.edge_corners(e);
    const Index ca = sides[0], cb = sides.size() == 2 ? sides[1] : kInvalidIndex;
    // Side ca runs a -> b in its face; the E-face runs against it.
    const Index a = topo.corner_vertex(ca), b = topo.corner_vertex(topo.corner_next(ca));
    const Index quad[4] = {topo.corner_next(ca), ca, cb != kInvalidIndex ? topo.corner_next(cb) : boundary_point(e, a),
                           cb != kInvalidIndex ? cb : boundary_point(e, b)};
    child.face_indices.insert(child.face_indices.end(), quad, quad + 4);
    close_face();
  }
  for (Index v = 0; v < nv; ++v) {
    const auto corners = topo.vertex_corners(v);
    const bool boundary = topo.vertex_kind(v) == VertexKind::boundary;
    // An interior vertex of valence 2 leaves a 2-gon: its E-faces already
    // share that edge.
    if (corners.empty() || (!boundary && corners.size() < 3)) continue;
    // Counter-clockwise around v: boundary edge e_0, faces, boundary edge e_k.
    const auto edges = topo.vertex_edges(v);
    if (boundary) child.face_indices.push_back(boundary_point(edges.front(), v));
    child.face_indices.insert(child.face_indices.end(), corners.begin(), corners.end());
    if (boundary) child.face_indices.push_back(boundary_point(edges.back(), v));
    close_face();
  }
  return map;
}

// One value per child vertex, from the parent face it lies in. A seam along
// an edge is not kept: the E- and V-faces that straddle it take each
// corner's own side's value.
void dual_split_face_varying(const MeshTopology& topo, const SplitMap& map, const PolygonMesh& child,
                             const FaceVaryingChannel& in, FaceVaryingChannel& out) {
  const auto k = static_cast<std::size_t>(in.components);
  out.name = in.name;
  out.components = in.components;
  out.values.assign(static_cast<std::size_t>(map.child_vertex_count) * k, 0.0);
  auto parent_value = [&](Index corner) {
    return in.values.data() + static_cast<std::size_t>(in.indices[static_cast<std::size_t>(corner)]) * k;
  };
  std::vector<double> centroid(k);
  for (Index f = 0; f < topo.face_count(); ++f) {
    const Index first = topo.face_first_corner(f), n = topo.face_size(f);
    std::fill(centroid.begin(), centroid.end(), 0.0);
    for (Index c = first; c < first + n; ++c)
      for (std::size_t j = 0; j < k; ++j) centroid[j] += parent_value(c)[j] / n;
    for (Index c = first; c < first + n; ++c)
      for (std::size_t j = 0; j < k; ++j)
        out.values[static_cast<std::size_t>(map.corner_point(c)) * k + j] = 0.5 * (parent_value(c)[j] + centroid[j]);
  }
  for (std::size_t r = 0; r < map.boundary_edges.size(); ++r) {
    const Index side = topo.edge_corners(map.boundary_edges[r])[0];
    const Index v0 = topo.edge_vertices(map.boundary_edges[r])[0];
    const Index near0 = topo.corner_vertex(side) == v0 ? side : topo.corner_next(side);
    const Index near1 = near0 == side ? topo.corner_next(side) : side;
    for (int end = 0; end < 2; ++end) {
      const double* a = parent_value(end == 0 ? near0 : near1);
      const double* b = parent_value(end == 0 ? near1 : near0);
      const std::size_t at = static_cast<std::size_t>(map.edge_points + 2 * static_cast<Index>(r) + end) * k;
      for (std::size_t j = 0; j < k; ++j) out.values[at + j] = 0.75 * a[j] + 0.25 * b[j];
    }
  }
  out.indices = child.face_indices;
}

}  // namespace subdiv::detail
