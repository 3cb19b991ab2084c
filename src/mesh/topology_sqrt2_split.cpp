// The topology of a sqrt2-split level of a closed mesh derived from its
// parent's, without the sorts of the generic construction (the split:
// src/topology/sqrt2_split.cpp). Child vertices are [face points F(f) = f |
// vertex points V(v) = nf + v]; child face e = [V(a), F(G), V(b), F(F)] for
// parent edge e whose first side runs a -> b in face F (G the other side).
// Every child edge is a spoke (F(f), V(v)) from a face point to one of its
// face's vertices: face f's spokes, in increasing v, are numbered from its
// first parent corner on, which is the generic (min, max) order.

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "topology_derived.h"

namespace subdiv {

std::optional<MeshTopology> MeshTopology::from_sqrt2_split(const MeshTopology& p, const PolygonMesh& child) {
  if (!p.all_rings_ordered()) return std::nullopt;
  const Index nf = p.face_count(), ne = p.edge_count(), nv = p.vertex_count(), nc = p.corner_count();
  if (child.vertex_count() != nf + nv || child.face_count() != ne) return std::nullopt;
  for (Index e = 0; e < ne; ++e)
    if (p.edge_face_count(e) != 2) return std::nullopt;  // closed manifold meshes only
  const Index vertex_point = nf;

  // Each face's vertices, sorted: the order of its spokes.
  std::vector<Index> sorted(p.corner_vertex_);
  bool simple = true;
  for (Index f = 0; f < nf && simple; ++f) {
    auto* begin = sorted.data() + p.face_first_corner(f);
    auto* end = begin + p.face_size(f);
    std::sort(begin, end);
    if (std::adjacent_find(begin, end) != end) simple = false;
  }
  if (!simple) return std::nullopt;
  auto face_of = [&](Index corner) { return p.corner_face(corner); };
  auto spoke = [&](Index f, Index v) {
    const Index* begin = sorted.data() + p.face_first_corner(f);
    return p.face_first_corner(f) + static_cast<Index>(std::lower_bound(begin, begin + p.face_size(f), v) - begin);
  };

  MeshTopology t;
  t.face_offsets_ = child.face_offsets;
  t.corner_vertex_ = child.face_indices;
  t.uniform_face_size_ = 4;
  const auto child_corners = static_cast<std::size_t>(4) * static_cast<std::size_t>(ne);
  const auto child_edges = static_cast<std::size_t>(nc);
  detail::assign_large(t.corner_edge_, child_corners);
  detail::assign_large(t.edge_vertices_, child_edges);
  detail::assign_large(t.edge_corner_offsets_, child_edges + 1);
  for (std::size_t e = 0; e <= child_edges; ++e) t.edge_corner_offsets_[e] = static_cast<Index>(2 * e);  // all interior
  detail::assign_large(t.edge_corners_, 2 * child_edges);

  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const auto sides = p.edge_corners(e);
      const Index F = face_of(sides[0]), G = face_of(sides[1]);
      const Index a = p.corner_vertex_[sides[0]], b = p.corner_vertex_[p.corner_next(sides[0])];
      Index* c = t.corner_edge_.data() + 4 * e;  // [V(a), F(G), V(b), F(F)]
      c[0] = spoke(G, a), c[1] = spoke(G, b), c[2] = spoke(F, b), c[3] = spoke(F, a);
    }
  });
  for (Index f = 0; f < nf; ++f)
    for (Index c = p.face_first_corner(f); c < p.face_first_corner(f) + p.face_size(f); ++c)
      t.edge_vertices_[static_cast<std::size_t>(c)] = {f, vertex_point + sorted[static_cast<std::size_t>(c)]};
  // Sides in increasing corner order: each spoke has exactly two.
  std::vector<std::uint8_t> filled(child_edges, 0);
  for (std::size_t c = 0; c < child_corners; ++c) {
    const auto edge = static_cast<std::size_t>(t.corner_edge_[c]);
    if (filled[edge] >= 2) return std::nullopt;
    t.edge_corners_[2 * edge + filled[edge]++] = static_cast<Index>(c);
  }

  const Index child_vertices = nf + nv;
  detail::assign_large(t.vertex_corner_offsets_, static_cast<std::size_t>(child_vertices) + 1, 0);
  detail::assign_large(t.vertex_edge_offsets_, static_cast<std::size_t>(child_vertices) + 1, 0);
  for (Index f = 0; f < nf; ++f) t.vertex_corner_offsets_[f + 1] = t.vertex_edge_offsets_[f + 1] = p.face_size(f);
  for (Index v = 0; v < nv; ++v) {
    t.vertex_corner_offsets_[vertex_point + v + 1] = p.vertex_face_count(v);
    t.vertex_edge_offsets_[vertex_point + v + 1] = p.valence(v);
  }
  t.lay_out_vertex_incidence();

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
    std::vector<Index> ring_corners, ring_edges;
    for (Index f = range.begin(); f != range.end(); ++f) {
      // Around F(f): the child face of edge e_i (v_i -> v_{i+1} in f) leaves
      // along the spoke to v_i and enters along the one to v_{i+1}.
      const Index n = p.face_size(f), first = p.face_first_corner(f);
      ring_corners.resize(static_cast<std::size_t>(n));
      ring_edges.resize(static_cast<std::size_t>(n));
      for (Index i = 0; i < n; ++i) {
        const Index c = first + i, e = p.corner_edge_[c];
        ring_corners[static_cast<std::size_t>(i)] = 4 * e + (p.edge_corners(e)[0] == c ? 3 : 1);
        ring_edges[static_cast<std::size_t>(i)] = spoke(f, p.corner_vertex_[c]);
      }
      write_ring(f, ring_corners.data(), ring_edges.data(), n);
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
        const Index e = edges[static_cast<std::size_t>(j)];
        ring_corners[static_cast<std::size_t>(j)] = 4 * e + (p.corner_vertex_[p.edge_corners(e)[0]] == v ? 0 : 2);
        ring_edges[static_cast<std::size_t>(j)] = spoke(face_of(faces[static_cast<std::size_t>((j + k - 1) % k)]), v);
      }
      write_ring(cv, ring_corners.data(), ring_edges.data(), k);
    }
  });
  t.build_boundary_loops();
  return t;
}

}  // namespace subdiv
