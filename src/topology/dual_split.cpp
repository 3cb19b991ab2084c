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
// Every face keeps the parent's orientation (checked in tests/rules/doo_sabin_test.cpp).

#include <algorithm>

#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "split_detail.h"
#include "subdiv/core/error.h"

namespace subdiv {

bool dual_split_has_v_face(const MeshTopology& topo, Index v) noexcept {
  const Index faces = topo.vertex_face_count(v);
  return faces > 0 && (topo.vertex_kind(v) == VertexKind::boundary || faces >= 3);
}

}  // namespace subdiv

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

  // Face sizes first, so that every face can be written in parallel.
  auto v_face_size = [&](Index v) -> Index {
    if (!dual_split_has_v_face(topo, v)) return 0;
    return topo.vertex_face_count(v) + (topo.vertex_kind(v) == VertexKind::boundary ? 2 : 0);
  };
  std::vector<Index> v_face_offset(static_cast<std::size_t>(nv) + 1, 0);
  Index v_faces = 0;
  for (Index v = 0; v < nv; ++v) {
    const Index n = v_face_size(v);
    v_face_offset[static_cast<std::size_t>(v) + 1] = v_face_offset[static_cast<std::size_t>(v)] + n;
    v_faces += n > 0;
  }
  const Index e_first = nc, v_first = nc + 4 * ne;  // where E- and V-faces start in face_indices
  const auto child_faces = static_cast<std::size_t>(nf + ne + v_faces);
  detail::assign_large(child.positions, static_cast<std::size_t>(map.child_vertex_count), Vec3{});
  detail::assign_large(child.face_offsets, child_faces + 1);
  detail::assign_large(child.face_indices, static_cast<std::size_t>(v_first + v_face_offset.back()));

  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      const Index first = topo.face_first_corner(f);
      child.face_offsets[static_cast<std::size_t>(f)] = first;
      for (Index c = first; c < first + topo.face_size(f); ++c) child.face_indices[static_cast<std::size_t>(c)] = c;
    }
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const auto sides = topo.edge_corners(e);
      const Index ca = sides[0], cb = sides.size() == 2 ? sides[1] : kInvalidIndex;
      // Side ca runs a -> b in its face; the E-face runs against it.
      const Index a = topo.corner_vertex(ca), b = topo.corner_vertex(topo.corner_next(ca));
      Index* q = child.face_indices.data() + e_first + 4 * e;
      q[0] = topo.corner_next(ca);
      q[1] = ca;
      q[2] = cb != kInvalidIndex ? topo.corner_next(cb) : boundary_point(e, a);
      q[3] = cb != kInvalidIndex ? cb : boundary_point(e, b);
      child.face_offsets[static_cast<std::size_t>(nf + e)] = e_first + 4 * e;
    }
  });
  // V-faces are numbered in vertex order among the vertices that have one.
  std::vector<Index> v_face_number(static_cast<std::size_t>(nv), kInvalidIndex);
  for (Index v = 0, n = nf + ne; v < nv; ++v)
    if (v_face_offset[static_cast<std::size_t>(v) + 1] > v_face_offset[static_cast<std::size_t>(v)])
      v_face_number[static_cast<std::size_t>(v)] = n++;
  tbb::parallel_for(tbb::blocked_range<Index>(0, nv, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Index number = v_face_number[static_cast<std::size_t>(v)];
      if (number == kInvalidIndex) continue;
      const Index offset = v_first + v_face_offset[static_cast<std::size_t>(v)];
      child.face_offsets[static_cast<std::size_t>(number)] = offset;
      Index* out = child.face_indices.data() + offset;
      // Counter-clockwise around v: boundary edge e_0, faces, boundary edge e_k.
      const auto edges = topo.vertex_edges(v);
      const bool boundary = topo.vertex_kind(v) == VertexKind::boundary;
      if (boundary) *out++ = boundary_point(edges.front(), v);
      for (const Index c : topo.vertex_corners(v)) *out++ = c;
      if (boundary) *out++ = boundary_point(edges.back(), v);
    }
  });
  child.face_offsets[child_faces] = static_cast<Index>(child.face_indices.size());
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
