// The topology of a sqrt2-split level of a closed mesh derived from its
// parent's, without the sorts of the generic construction (the split:
// src/topology/sqrt2_split.cpp). Child vertices are [face points F(f) = f |
// vertex points V(v) = nf + v]; child face e = [V(a), F(G), V(b), F(F)] for
// parent edge e whose first side runs a -> b in face F (G the other side).
// Every child edge is a spoke (F(f), V(v)) from a face point to one of its
// face's vertices: face f's spokes, in increasing v, are numbered from its
// first parent corner on, which is the generic (min, max) order. Every array
// is written by parallel loops over parent faces, edges or vertices, each
// element by one iteration (each parent corner knows its spoke).

#include <algorithm>
#include <atomic>

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

  // Closed meshes (ordered rings: consistently oriented) without a repeated
  // corner vertex:
  // a face's spokes, in increasing v, are numbered from its first corner on,
  // so the spoke of corner c is its face's first corner plus the rank of c's
  // vertex among the face's.
  std::vector<Index> spoke_of(static_cast<std::size_t>(nc));
  std::atomic<bool> simple = true;
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      const Index first = p.face_first_corner(f), n = p.face_size(f);
      const Index* v = p.corner_vertex_.data() + first;
      for (Index i = 0; i < n; ++i) {
        Index rank = 0;
        for (Index j = 0; j < n; ++j) {
          rank += v[j] < v[i];
          if (j != i && v[j] == v[i]) simple = false;
        }
        spoke_of[static_cast<std::size_t>(first + i)] = first + rank;
      }
    }
  });
  if (!simple) return std::nullopt;

  MeshTopology t;
  t.face_offsets_ = child.face_offsets;
  t.corner_vertex_ = child.face_indices;
  t.uniform_face_size_ = 4;
  const auto child_corners = static_cast<std::size_t>(4) * static_cast<std::size_t>(ne);
  const auto child_edges = static_cast<std::size_t>(nc);
  detail::assign_large(t.corner_edge_, child_corners);
  detail::assign_large(t.edge_vertices_, child_edges);
  detail::assign_large(t.edge_corner_offsets_, child_edges + 1);
  detail::assign_large(t.edge_corners_, 2 * child_edges);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, child_edges + 1, 16384), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t e = range.begin(); e != range.end(); ++e) t.edge_corner_offsets_[e] = static_cast<Index>(2 * e);  // all interior
  });

  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const auto sides = p.edge_corners(e);
      // F's side runs a -> b, G's b -> a.
      const Index Fa = sides[0], Fb = p.corner_next(sides[0]), Gb = sides[1], Ga = p.corner_next(sides[1]);
      Index* c = t.corner_edge_.data() + 4 * e;  // [V(a), F(G), V(b), F(F)]
      c[0] = spoke_of[Ga], c[1] = spoke_of[Gb], c[2] = spoke_of[Fb], c[3] = spoke_of[Fa];
    }
  });
  t.lay_out_point_split_incidence(p, 0);  // a face point: its face's corners and edges
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 4096), [&](const tbb::blocked_range<Index>& range) {
    std::vector<Index> ring_corners, ring_edges;
    std::vector<char> first_side;  // f is e_i's F, v_i its a
    for (Index f = range.begin(); f != range.end(); ++f) {
      // Around F(f): the child face of edge e_i (v_i -> v_{i+1} in f) leaves
      // along the spoke to v_i and enters along the one to v_{i+1}.
      const Index n = p.face_size(f), first = p.face_first_corner(f);
      ring_corners.resize(static_cast<std::size_t>(n));
      ring_edges.resize(static_cast<std::size_t>(n));
      first_side.resize(static_cast<std::size_t>(n));
      for (Index i = 0; i < n; ++i)
        first_side[static_cast<std::size_t>(i)] = p.edge_corners(p.corner_edge_[first + i])[0] == first + i;
      for (Index i = 0; i < n; ++i) {
        const Index c = first + i, prev = i == 0 ? n - 1 : i - 1;
        ring_corners[static_cast<std::size_t>(i)] = 4 * p.corner_edge_[c] + (first_side[static_cast<std::size_t>(i)] ? 3 : 1);
        ring_edges[static_cast<std::size_t>(i)] = spoke_of[static_cast<std::size_t>(c)];
        // The spoke to v_i: its sides are this ring corner and, in the child
        // face of e_prev (entering v_i), V(b) if f is e_prev's F, else V(a).
        const Index here = ring_corners[static_cast<std::size_t>(i)];
        const Index other = 4 * p.corner_edge_[first + prev] + (first_side[static_cast<std::size_t>(prev)] ? 2 : 0);
        const auto spoke = static_cast<std::size_t>(ring_edges[static_cast<std::size_t>(i)]);
        t.edge_vertices_[spoke] = {f, vertex_point + p.corner_vertex_[c]};
        t.edge_corners_[2 * spoke] = std::min(here, other);
        t.edge_corners_[2 * spoke + 1] = std::max(here, other);
      }
      t.write_ring_from_smallest_corner(f, ring_corners.data(), ring_edges.data(), n);
    }
  });
  t.derive_vertex_point_rings(p, vertex_point, 4, spoke_of);
  t.build_boundary_loops();
  return t;
}

}  // namespace subdiv
