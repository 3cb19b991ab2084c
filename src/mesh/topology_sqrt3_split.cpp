// The topology of a sqrt3-split level of a closed triangle mesh derived from
// its parent's, without the sorts of the generic construction (the split:
// src/topology/sqrt3_split.cpp). Child vertices are [face points F(f) = f |
// vertex points V(v) = nf + v]; child faces 2e = [V(a), F(G), F(F)] and
// 2e+1 = [V(b), F(F), F(G)] for parent edge e whose first side runs a -> b
// in face F (G the other side). Every child edge has a face point as its
// smaller end: face point f's edges are the flipped edges (F(f), F(g)) to
// its neighbours g > f, in increasing g, then its spokes (F(f), V(v)) to its
// corners, in increasing v: the generic (min, max) order.

#include <algorithm>
#include <array>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "topology_derived.h"

namespace subdiv {

std::optional<MeshTopology> MeshTopology::from_sqrt3_split(const MeshTopology& p, const PolygonMesh& child) {
  if (!p.all_rings_ordered()) return std::nullopt;
  const Index nf = p.face_count(), ne = p.edge_count(), nv = p.vertex_count();
  if (child.vertex_count() != nf + nv || child.face_count() != 2 * ne) return std::nullopt;  // a trisecting step
  for (Index f = 0; f < nf; ++f)
    if (p.face_size(f) != 3) return std::nullopt;
  for (Index e = 0; e < ne; ++e)
    if (p.edge_face_count(e) != 2) return std::nullopt;  // closed manifold meshes only
  const Index vertex_point = nf;
  auto face_of = [&](Index corner) { return corner / 3; };

  // Per face: its neighbours g > f (sorted) and its corners' vertices (sorted).
  // Two faces sharing two edges would merge flipped edges: generic build.
  std::vector<std::array<Index, 3>> partners(static_cast<std::size_t>(nf)), corners(static_cast<std::size_t>(nf));
  std::vector<Index> first(static_cast<std::size_t>(nf) + 1, 0);
  std::vector<Index> partner_count(static_cast<std::size_t>(nf), 0);
  bool simple = true;
  for (Index f = 0; f < nf && simple; ++f) {
    Index n = 0;
    for (Index i = 0; i < 3; ++i) {
      const auto sides = p.edge_corners(p.corner_edge_[3 * f + i]);
      const Index g = face_of(sides[0]) == f ? face_of(sides[1]) : face_of(sides[0]);
      if (g == f) simple = false;
      if (g > f) partners[f][n++] = g;
      corners[f][i] = p.corner_vertex_[3 * f + i];
    }
    std::sort(partners[f].begin(), partners[f].begin() + n);
    std::sort(corners[f].begin(), corners[f].end());
    if (std::adjacent_find(partners[f].begin(), partners[f].begin() + n) != partners[f].begin() + n) simple = false;
    if (std::adjacent_find(corners[f].begin(), corners[f].end()) != corners[f].end()) simple = false;
    partner_count[f] = n;
    first[f + 1] = first[f] + n + 3;
  }
  if (!simple) return std::nullopt;
  const Index child_edges = first.back();
  auto flipped = [&](Index f, Index g) {
    const Index lo = std::min(f, g), hi = std::max(f, g);
    const Index* begin = partners[lo].data();
    return first[lo] + static_cast<Index>(std::lower_bound(begin, begin + partner_count[lo], hi) - begin);
  };
  auto spoke = [&](Index f, Index v) {
    const Index* begin = corners[f].data();
    return first[f] + partner_count[f] + static_cast<Index>(std::lower_bound(begin, begin + 3, v) - begin);
  };

  MeshTopology t;
  t.face_offsets_ = child.face_offsets;
  t.corner_vertex_ = child.face_indices;
  t.uniform_face_size_ = 3;
  const auto child_corners = static_cast<std::size_t>(6) * static_cast<std::size_t>(ne);
  detail::assign_large(t.corner_edge_, child_corners);
  detail::assign_large(t.edge_vertices_, static_cast<std::size_t>(child_edges));
  detail::assign_large(t.edge_corner_offsets_, static_cast<std::size_t>(child_edges) + 1);
  for (Index e = 0; e <= child_edges; ++e) t.edge_corner_offsets_[static_cast<std::size_t>(e)] = 2 * e;  // all interior
  detail::assign_large(t.edge_corners_, 2 * static_cast<std::size_t>(child_edges));

  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const auto sides = p.edge_corners(e);
      const Index F = face_of(sides[0]), G = face_of(sides[1]);
      const Index a = p.corner_vertex_[sides[0]], b = p.corner_vertex_[p.corner_next(sides[0])];
      Index* c = t.corner_edge_.data() + 6 * e;
      c[0] = spoke(G, a), c[1] = flipped(F, G), c[2] = spoke(F, a);  // [V(a), F(G), F(F)]
      c[3] = spoke(F, b), c[4] = c[1], c[5] = spoke(G, b);           // [V(b), F(F), F(G)]
      t.edge_vertices_[static_cast<std::size_t>(c[1])] = {std::min(F, G), std::max(F, G)};
    }
  });
  for (Index f = 0; f < nf; ++f)
    for (const Index v : corners[f]) t.edge_vertices_[static_cast<std::size_t>(spoke(f, v))] = {f, vertex_point + v};
  // Sides in increasing corner order: each edge has exactly two.
  std::vector<std::uint8_t> filled(static_cast<std::size_t>(child_edges), 0);
  for (std::size_t c = 0; c < child_corners; ++c) {
    const auto edge = static_cast<std::size_t>(t.corner_edge_[c]);
    if (filled[edge] >= 2) return std::nullopt;
    t.edge_corners_[2 * edge + filled[edge]++] = static_cast<Index>(c);
  }

  // Vertex incidence: a face point has 6 corners and edges, a vertex point
  // its parent's valence.
  const Index child_vertices = nf + nv;
  detail::assign_large(t.vertex_corner_offsets_, static_cast<std::size_t>(child_vertices) + 1, 0);
  detail::assign_large(t.vertex_edge_offsets_, static_cast<std::size_t>(child_vertices) + 1, 0);
  for (Index f = 0; f < nf; ++f) t.vertex_corner_offsets_[f + 1] = t.vertex_edge_offsets_[f + 1] = 6;
  for (Index v = 0; v < nv; ++v) {
    t.vertex_corner_offsets_[vertex_point + v + 1] = p.vertex_face_count(v);
    t.vertex_edge_offsets_[vertex_point + v + 1] = p.valence(v);
  }
  t.lay_out_vertex_incidence();

  // The child corner at V(v) and at F(f) in the child faces of parent edge e.
  auto corner_at_vertex = [&](Index e, Index v) { return 6 * e + (p.corner_vertex_[p.edge_corners(e)[0]] == v ? 0 : 3); };
  // Face j of a ring leaves its vertex along edge j and enters along j + 1;
  // rings start at their smallest corner (the generic walk's order).
  auto write_ring = [&](Index cv, const Index* ring_corners, const Index* ring_edges, Index n) {
    const auto start = std::min_element(ring_corners, ring_corners + n) - ring_corners;
    Index* out_c = t.vertex_corners_.data() + t.vertex_corner_offsets_[cv];
    Index* out_e = t.vertex_edges_.data() + t.vertex_edge_offsets_[cv];
    for (Index k = 0; k < n; ++k) {
      out_c[k] = ring_corners[(start + k) % n];
      out_e[k] = ring_edges[(start + k) % n];
    }
  };
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      // Around F(f): at v_i from e_i (leaving along the spoke to v_i), then at
      // v_{i+1} from e_i (leaving along e_i's flipped edge).
      Index ring_corners[6], ring_edges[6];
      for (Index i = 0; i < 3; ++i) {
        const Index c = 3 * f + i, e = p.corner_edge_[c];
        const Index v = p.corner_vertex_[c], next = p.corner_vertex_[p.corner_next(c)];
        const auto sides = p.edge_corners(e);
        const Index g = face_of(sides[0]) == f ? face_of(sides[1]) : face_of(sides[0]);
        ring_corners[2 * i] = corner_at_vertex(e, v) + 2;
        ring_corners[2 * i + 1] = corner_at_vertex(e, next) + 1;
        ring_edges[2 * i] = spoke(f, v);
        ring_edges[2 * i + 1] = flipped(f, g);
      }
      write_ring(f, ring_corners, ring_edges, 6);
    }
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, nv, 4096), [&](const tbb::blocked_range<Index>& range) {
    std::vector<Index> ring_corners, ring_edges;
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Index cv = vertex_point + v;
      if (p.vertex_kind_[v] == VertexKind::isolated) {
        t.vertex_kind_[cv] = VertexKind::isolated;
        t.ring_ordered_[cv] = 0;
        t.fan_count_[cv] = 0;
        continue;
      }
      // The child face of ring edge e_j lies between the spokes to faces
      // j - 1 (leaving) and j (entering).
      const auto faces = p.vertex_corners(v);
      const auto edges = p.vertex_edges(v);
      const auto k = static_cast<Index>(edges.size());
      ring_corners.resize(static_cast<std::size_t>(k));
      ring_edges.resize(static_cast<std::size_t>(k));
      for (Index j = 0; j < k; ++j) {
        ring_corners[static_cast<std::size_t>(j)] = corner_at_vertex(edges[static_cast<std::size_t>(j)], v);
        ring_edges[static_cast<std::size_t>(j)] = spoke(face_of(faces[static_cast<std::size_t>((j + k - 1) % k)]), v);
      }
      write_ring(cv, ring_corners.data(), ring_edges.data(), k);
    }
  });
  t.build_boundary_loops();
  return t;
}

}  // namespace subdiv
