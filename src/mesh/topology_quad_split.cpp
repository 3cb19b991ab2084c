// The topology of a quad-split level derived from its parent's, without the
// sorts of the generic construction. Edges come out in the generic (min, max)
// order: child vertices are numbered [face points F(f) | edge points E(e) |
// vertex points V(v)], so the edges whose smaller end is F(f) are the face's
// interior edges (F(f), E(e_c)), in increasing e_c, and those whose smaller
// end is E(e) are the two halves (E(e), V(a)), (E(e), V(b)) with a < b.
// Rings: a face point's runs over its face's corners, a vertex point's
// follows its parent's ring, an edge point's is written out (valence <= 4).

#include <algorithm>
#include <numeric>

#include "../core/large_buffers.h"
#include "topology_derived.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace subdiv {

bool MeshTopology::all_rings_ordered() const noexcept {
  for (Index v = 0; v < vertex_count(); ++v)
    if (!ring_ordered_[v] && vertex_kind_[v] != VertexKind::isolated) return false;
  return true;
}

std::optional<MeshTopology> MeshTopology::from_quad_split(const MeshTopology& p, const PolygonMesh& child) {
  if (!p.all_rings_ordered()) return std::nullopt;
  const Index nf = p.face_count(), ne = p.edge_count(), nv = p.vertex_count(), nc = p.corner_count();
  const Index face_point = 0, edge_point = nf, vertex_point = nf + ne;
  MeshTopology t;
  t.face_offsets_ = child.face_offsets;
  t.corner_vertex_ = child.face_indices;
  const auto child_corners = static_cast<std::size_t>(4) * static_cast<std::size_t>(nc);
  t.uniform_face_size_ = 4;
  detail::assign_large(t.corner_edge_, child_corners);

  // Interior edge of parent corner c: (F(f), E(e_c)), numbered by the rank of
  // e_c among its face's edges.
  std::vector<Index> interior(static_cast<std::size_t>(nc));
  const Index halves = nc;  // first half-edge index
  auto half = [&](Index e, Index end) { return halves + 2 * e + (p.edge_vertices_[e][0] == end ? 0 : 1); };

  detail::assign_large(t.edge_vertices_, static_cast<std::size_t>(nc) + 2 * static_cast<std::size_t>(ne));
  detail::assign_large(t.edge_corner_offsets_, t.edge_vertices_.size() + 1);
  detail::assign_large(t.edge_corners_, 2 * static_cast<std::size_t>(nc) + 2 * p.edge_corners_.size());
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 2048), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      const Index first = p.face_offsets_[f], last = p.face_offsets_[f + 1];
      for (Index c = first; c < last; ++c) {
        Index rank = 0;
        for (Index d = first; d < last; ++d) rank += p.corner_edge_[d] < p.corner_edge_[c];
        interior[c] = first + rank;
      }
      for (Index c = first; c < last; ++c) {
        const Index e = interior[c], next = p.corner_next(c), prev = p.corner_prev(c);
        t.edge_vertices_[e] = {face_point + f, edge_point + p.corner_edge_[c]};
        t.edge_corner_offsets_[e] = 2 * e;
        const Index sides[2] = {std::min(4 * c + 1, 4 * next + 2), std::max(4 * c + 1, 4 * next + 2)};
        std::copy(sides, sides + 2, t.edge_corners_.begin() + 2 * e);
        const Index v = p.corner_vertex_[c];
        t.corner_edge_[4 * c + 0] = half(p.corner_edge_[c], v);
        t.corner_edge_[4 * c + 1] = e;
        t.corner_edge_[4 * c + 3] = half(p.corner_edge_[prev], v);
      }
      for (Index c = first; c < last; ++c) t.corner_edge_[4 * c + 2] = interior[p.corner_prev(c)];
    }
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const auto sides = p.edge_corners(e);
      const auto k = static_cast<Index>(sides.size());
      for (Index h = 0; h < 2; ++h) {
        const Index end = p.edge_vertices_[e][h];
        const Index ce = halves + 2 * e + h;
        t.edge_vertices_[ce] = {edge_point + e, vertex_point + end};
        const Index offset = 2 * nc + 2 * p.edge_corner_offsets_[e] + h * k;
        t.edge_corner_offsets_[ce] = offset;
        auto out = t.edge_corners_.begin() + offset;
        for (const Index s : sides) *out++ = p.corner_vertex_[s] == end ? 4 * s + 0 : 4 * p.corner_next(s) + 3;
        std::sort(t.edge_corners_.begin() + offset, out);
      }
    }
  });
  t.edge_corner_offsets_.back() = static_cast<Index>(t.edge_corners_.size());

  // Vertex incidence: face points, edge points, vertex points.
  const Index child_vertices = nf + ne + nv;
  detail::assign_large(t.vertex_corner_offsets_, static_cast<std::size_t>(child_vertices) + 1);
  detail::assign_large(t.vertex_edge_offsets_, static_cast<std::size_t>(child_vertices) + 1);
  t.vertex_corner_offsets_[0] = t.vertex_edge_offsets_[0] = 0;
  for (Index f = 0; f < nf; ++f) {
    t.vertex_corner_offsets_[face_point + f + 1] = p.face_size(f);
    t.vertex_edge_offsets_[face_point + f + 1] = p.face_size(f);
  }
  for (Index e = 0; e < ne; ++e) {
    t.vertex_corner_offsets_[edge_point + e + 1] = 2 * p.edge_face_count(e);
    t.vertex_edge_offsets_[edge_point + e + 1] = 2 + p.edge_face_count(e);
  }
  for (Index v = 0; v < nv; ++v) {
    t.vertex_corner_offsets_[vertex_point + v + 1] = p.vertex_face_count(v);
    t.vertex_edge_offsets_[vertex_point + v + 1] = p.valence(v);
  }
  t.lay_out_vertex_incidence();

  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 2048), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      Index* corners = t.vertex_corners_.data() + t.vertex_corner_offsets_[face_point + f];
      Index* edges = t.vertex_edges_.data() + t.vertex_edge_offsets_[face_point + f];
      for (Index c = p.face_offsets_[f]; c < p.face_offsets_[f + 1]; ++c) {
        *corners++ = 4 * c + 2;
        *edges++ = interior[p.corner_prev(c)];
      }
    }
  });
  // An edge point's ring, written in the order the generic walk
  // (order_ring) gives: around an interior edge from side s0 (running a -> b)
  // and side s1, the corners 4 s0 + 1, 4 next(s1) + 3, 4 s1 + 1, 4 next(s0) + 3
  // with outgoing edges interior(s0), half(a), interior(s1), half(b), rotated
  // to start at the smallest corner; on a boundary edge, from the corner whose
  // outgoing edge is the boundary half.
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const Index v = edge_point + e;
      Index* corners = t.vertex_corners_.data() + t.vertex_corner_offsets_[v];
      Index* edges = t.vertex_edges_.data() + t.vertex_edge_offsets_[v];
      const auto sides = p.edge_corners(e);
      const Index s0 = sides[0], n0 = p.corner_next(s0);
      const Index a = p.corner_vertex_[s0], b = p.corner_vertex_[n0];
      if (sides.size() == 1) {
        t.vertex_kind_[v] = VertexKind::boundary;
        const Index ring_corners[2] = {4 * n0 + 3, 4 * s0 + 1};
        const Index ring_edges[3] = {half(e, b), interior[s0], half(e, a)};
        std::copy(ring_corners, ring_corners + 2, corners);
        std::copy(ring_edges, ring_edges + 3, edges);
        continue;
      }
      const Index s1 = sides[1], n1 = p.corner_next(s1);
      const Index ring_corners[4] = {4 * s0 + 1, 4 * n1 + 3, 4 * s1 + 1, 4 * n0 + 3};
      const Index ring_edges[4] = {interior[s0], half(e, a), interior[s1], half(e, b)};
      const auto first = std::min_element(ring_corners, ring_corners + 4) - ring_corners;
      for (std::ptrdiff_t i = 0; i < 4; ++i) {
        corners[i] = ring_corners[(first + i) % 4];
        edges[i] = ring_edges[(first + i) % 4];
      }
    }
  });
  t.inherit_vertex_points(p, vertex_point, [](Index c) { return 4 * c; }, half);
  t.build_boundary_loops();
  return t;
}

}  // namespace subdiv
