// The topology of a triangle-split level derived from its parent's, without
// the sorts of the generic construction. Child vertices are numbered
// [edge points E(e) | vertex points V(v)], so the edges whose smaller end is
// E(e) are its interior edges (E(e), E(e')), e' > e, in increasing e', then
// its two halves (E(e), V(a)), (E(e), V(b)), a < b: the generic (min, max)
// order. Child face 4f+i = [V(v_i), E(e_i), E(e_{i-1})] (e_i leaves corner
// i), 4f+3 = [E(e_0), E(e_1), E(e_2)].

#include <algorithm>
#include <atomic>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "topology_derived.h"

namespace subdiv {

std::optional<MeshTopology> MeshTopology::from_triangle_split(const MeshTopology& p, const PolygonMesh& child) {
  if (!p.all_rings_ordered()) return std::nullopt;
  const Index nf = p.face_count(), ne = p.edge_count(), nv = p.vertex_count();
  for (Index f = 0; f < nf; ++f)
    if (p.face_size(f) != 3) return std::nullopt;
  const Index vertex_point = ne;

  // The interior partners of each edge point: the other edges of its faces
  // with a larger index. A repeated partner (two faces on the same three
  // vertices) would merge child edges: leave that to the generic build.
  std::vector<Index> first(static_cast<std::size_t>(ne) + 1, 0);
  std::vector<Index> partner_offsets(static_cast<std::size_t>(ne) + 1, 0);
  for (Index e = 0; e < ne; ++e) partner_offsets[e + 1] = partner_offsets[e] + 2 * p.edge_face_count(e);
  std::vector<Index> partners(static_cast<std::size_t>(partner_offsets.back()));
  std::atomic<bool> simple = true;
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      Index* out = partners.data() + partner_offsets[e];
      Index* begin = out;
      for (const Index s : p.edge_corners(e)) {
        for (const Index other : {p.corner_edge_[p.corner_next(s)], p.corner_edge_[p.corner_prev(s)]})
          if (other > e) *out++ = other;
      }
      std::sort(begin, out);
      if (std::adjacent_find(begin, out) != out) simple = false;
      first[e + 1] = static_cast<Index>(out - begin) + 2;
    }
  });
  if (!simple) return std::nullopt;
  std::partial_sum(first.begin(), first.end(), first.begin());
  const Index child_edges = first.back();

  auto interior = [&](Index a, Index b) {  // the child edge (E(a), E(b))
    const Index lo = std::min(a, b), hi = std::max(a, b);
    const Index* begin = partners.data() + partner_offsets[lo];
    const Index* end = begin + (first[lo + 1] - first[lo] - 2);
    return first[lo] + static_cast<Index>(std::lower_bound(begin, end, hi) - begin);
  };
  auto half = [&](Index e, Index end) { return first[e + 1] - 2 + (p.edge_vertices_[e][0] == end ? 0 : 1); };

  MeshTopology t;
  t.face_offsets_ = child.face_offsets;
  t.corner_vertex_ = child.face_indices;
  const auto child_corners = static_cast<std::size_t>(12) * static_cast<std::size_t>(nf);
  t.uniform_face_size_ = 3;
  detail::assign_large(t.corner_edge_, child_corners);
  detail::assign_large(t.edge_vertices_, static_cast<std::size_t>(child_edges));
  detail::assign_large(t.edge_corner_offsets_, static_cast<std::size_t>(child_edges) + 1, 0);

  // Side counts: interior edges have two, halves as many as their parent.
  for (Index e = 0; e < ne; ++e) {
    for (Index i = first[e]; i < first[e + 1] - 2; ++i) t.edge_corner_offsets_[i + 1] = 2;
    t.edge_corner_offsets_[first[e + 1] - 1] = p.edge_face_count(e);
    t.edge_corner_offsets_[first[e + 1]] = p.edge_face_count(e);
  }
  std::partial_sum(t.edge_corner_offsets_.begin(), t.edge_corner_offsets_.end(), t.edge_corner_offsets_.begin());
  detail::assign_large(t.edge_corners_, static_cast<std::size_t>(t.edge_corner_offsets_.back()));

  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 2048), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      Index v[3], e[3];
      for (Index i = 0; i < 3; ++i) {
        v[i] = p.corner_vertex_[3 * f + i];
        e[i] = p.corner_edge_[3 * f + i];
      }
      for (Index i = 0; i < 3; ++i) {
        const Index prev = (i + 2) % 3;
        Index* c = t.corner_edge_.data() + 12 * f + 3 * i;
        c[0] = half(e[i], v[i]);
        c[1] = interior(e[i], e[prev]);
        c[2] = half(e[prev], v[i]);
        t.corner_edge_[12 * f + 9 + i] = interior(e[i], e[(i + 1) % 3]);
        // Sides of the interior edge (E(e_i), E(e_prev)): corner 1 of child face
        // 4f+i and corner prev of the centre. Each face owns its interior edges.
        const Index ie = c[1];
        const Index a = 12 * f + 3 * i + 1, b = 12 * f + 9 + prev;
        t.edge_vertices_[ie] = {std::min(e[i], e[prev]), std::max(e[i], e[prev])};
        t.edge_corners_[t.edge_corner_offsets_[ie]] = std::min(a, b);
        t.edge_corners_[t.edge_corner_offsets_[ie] + 1] = std::max(a, b);
      }
    }
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      for (Index h = 0; h < 2; ++h) {
        const Index end = p.edge_vertices_[e][h];
        const Index ce = first[e + 1] - 2 + h;
        t.edge_vertices_[ce] = {e, vertex_point + end};
        Index* out = t.edge_corners_.data() + t.edge_corner_offsets_[ce];
        Index* begin = out;
        for (const Index s : p.edge_corners(e)) {
          const Index f = s / 3, i = s % 3;
          *out++ = p.corner_vertex_[s] == end ? 12 * f + 3 * i : 12 * f + 3 * ((i + 1) % 3) + 2;
        }
        std::sort(begin, out);
      }
    }
  });

  // Vertex incidence: edge points (written out), then vertex points (inherited).
  const Index child_vertices = ne + nv;
  detail::assign_large(t.vertex_corner_offsets_, static_cast<std::size_t>(child_vertices) + 1, 0);
  detail::assign_large(t.vertex_edge_offsets_, static_cast<std::size_t>(child_vertices) + 1, 0);
  for (Index e = 0; e < ne; ++e) {
    t.vertex_corner_offsets_[e + 1] = 3 * p.edge_face_count(e);
    t.vertex_edge_offsets_[e + 1] = 2 + 2 * p.edge_face_count(e);
  }
  for (Index v = 0; v < nv; ++v) {
    t.vertex_corner_offsets_[vertex_point + v + 1] = p.vertex_face_count(v);
    t.vertex_edge_offsets_[vertex_point + v + 1] = p.valence(v);
  }
  t.lay_out_vertex_incidence();

  // An edge point's ring, written in the order the generic walk
  // (order_ring) gives. In face f, from side s = corner i (edge e running
  // a -> b), the corners are 12f + 3(i+1) + 2, 12f + 9 + i, 12f + 3i + 1 with
  // outgoing edges half(b), interior(e, next edge), interior(e, previous
  // edge); the other side follows the same way, and the ring is rotated to
  // start at the smallest corner. A boundary edge point starts at the corner
  // whose outgoing edge is the boundary half(b) and ends with half(a).
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      Index ring_corners[6], ring_edges[7];
      Index n = 0;
      for (const Index s : p.edge_corners(e)) {
        const Index f = s / 3, i = s % 3;
        ring_corners[n] = 12 * f + 3 * ((i + 1) % 3) + 2;
        ring_corners[n + 1] = 12 * f + 9 + i;
        ring_corners[n + 2] = 12 * f + 3 * i + 1;
        ring_edges[n] = half(e, p.corner_vertex_[p.corner_next(s)]);
        ring_edges[n + 1] = interior(e, p.corner_edge_[p.corner_next(s)]);
        ring_edges[n + 2] = interior(e, p.corner_edge_[p.corner_prev(s)]);
        n += 3;
      }
      Index* corners = t.vertex_corners_.data() + t.vertex_corner_offsets_[e];
      Index* edges = t.vertex_edges_.data() + t.vertex_edge_offsets_[e];
      if (n == 3) {
        t.vertex_kind_[e] = VertexKind::boundary;
        ring_edges[3] = half(e, p.corner_vertex_[p.edge_corners(e)[0]]);
        std::copy(ring_corners, ring_corners + 3, corners);
        std::copy(ring_edges, ring_edges + 4, edges);
        continue;
      }
      const auto first_corner = std::min_element(ring_corners, ring_corners + 6) - ring_corners;
      for (std::ptrdiff_t k = 0; k < 6; ++k) {
        corners[k] = ring_corners[(first_corner + k) % 6];
        edges[k] = ring_edges[(first_corner + k) % 6];
      }
    }
  });
  t.inherit_vertex_points(p, vertex_point, [](Index c) { return 12 * (c / 3) + 3 * (c % 3); }, half);
  t.build_boundary_loops();
  return t;
}

}  // namespace subdiv
