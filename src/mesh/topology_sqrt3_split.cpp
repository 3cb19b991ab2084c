// The topology of a sqrt3-split level of a closed triangle mesh derived from
// its parent's, without the sorts of the generic construction (the split:
// src/topology/sqrt3_split.cpp). Child vertices are [face points F(f) = f |
// vertex points V(v) = nf + v]; child faces 2e = [V(a), F(G), F(F)] and
// 2e+1 = [V(b), F(F), F(G)] for parent edge e whose first side runs a -> b
// in face F (G the other side). Every child edge has a face point as its
// smaller end: face point f's edges are the flipped edges (F(f), F(g)) to
// its neighbours g > f, in increasing g, then its spokes (F(f), V(v)) to its
// corners, in increasing v: the generic (min, max) order.
//
// Every array is written by parallel loops over parent faces, edges or
// vertices, each element by one iteration: the child edges are numbered
// first (per face, then a prefix sum), and each parent corner and edge
// remembers its child edge (its spoke, its flipped edge) for the later loops.

#include <algorithm>
#include <atomic>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "topology_derived.h"

namespace subdiv {

namespace {

// The rank of x among the n values a[0..n) (how many are smaller).
inline Index rank_among(const Index* a, Index n, Index x) {
  Index r = 0;
  for (Index i = 0; i < n; ++i) r += a[i] < x;
  return r;
}

}  // namespace

std::optional<MeshTopology> MeshTopology::from_sqrt3_split(const MeshTopology& p, const PolygonMesh& child) {
  if (!p.all_rings_ordered()) return std::nullopt;
  const Index nf = p.face_count(), ne = p.edge_count(), nv = p.vertex_count();
  if (child.vertex_count() != nf + nv || child.face_count() != 2 * ne) return std::nullopt;  // a trisecting step
  if (p.uniform_face_size_ != 3) return std::nullopt;  // triangles only
  const Index vertex_point = nf;
  auto face_of = [](Index corner) { return corner / 3; };
  auto next_of = [](Index corner) { return corner % 3 == 2 ? corner - 2 : corner + 1; };

  // Closed manifold meshes only (ordered rings: consistently oriented); a
  // face next to itself, two faces sharing two edges (merged flipped edges)
  // or a repeated corner vertex go to the generic build. Per face: its
  // neighbours across its three edges, and its number of child edges
  // (partners g > f, then three spokes).
  std::vector<Index> neighbour(3 * static_cast<std::size_t>(nf));
  std::vector<Index> first(static_cast<std::size_t>(nf) + 1, 0);
  std::atomic<bool> simple = true;
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      Index n = 0;
      const Index* v = p.corner_vertex_.data() + 3 * f;
      if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) simple = false;
      Index* g = neighbour.data() + 3 * f;
      for (Index i = 0; i < 3; ++i) {
        const Index e = p.corner_edge_[3 * f + i];
        if (p.edge_face_count(e) != 2) {
          simple = false;
          g[i] = f;
          continue;
        }
        const auto sides = p.edge_corners(e);
        g[i] = face_of(sides[0] == 3 * f + i ? sides[1] : sides[0]);
        if (g[i] == f) simple = false;
        n += g[i] > f;
      }
      if (g[0] == g[1] || g[1] == g[2] || g[0] == g[2]) simple = false;
      first[static_cast<std::size_t>(f) + 1] = n + 3;
    }
  });
  if (!simple) return std::nullopt;
  std::partial_sum(first.begin(), first.end(), first.begin());
  const Index child_edges = first.back();

  // The child edge of each parent corner (its face's spoke to its vertex)
  // and of each parent edge (the flipped edge, numbered at its smaller face).
  std::vector<Index> spoke_of(3 * static_cast<std::size_t>(nf)), flipped_of(static_cast<std::size_t>(ne));
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      const Index* v = p.corner_vertex_.data() + 3 * f;
      const Index* g = neighbour.data() + 3 * f;
      Index larger[3], n = 0;
      for (Index i = 0; i < 3; ++i)
        if (g[i] > f) larger[n++] = g[i];
      for (Index i = 0; i < 3; ++i) {
        spoke_of[3 * static_cast<std::size_t>(f) + i] = first[f] + n + rank_among(v, 3, v[i]);
        if (g[i] > f) flipped_of[static_cast<std::size_t>(p.corner_edge_[3 * f + i])] = first[f] + rank_among(larger, n, g[i]);
      }
    }
  });

  MeshTopology t;
  t.face_offsets_ = child.face_offsets;
  t.corner_vertex_ = child.face_indices;
  t.uniform_face_size_ = 3;
  const auto child_corners = static_cast<std::size_t>(6) * static_cast<std::size_t>(ne);
  detail::assign_large(t.corner_edge_, child_corners);
  detail::assign_large(t.edge_vertices_, static_cast<std::size_t>(child_edges));
  detail::assign_large(t.edge_corner_offsets_, static_cast<std::size_t>(child_edges) + 1);
  detail::assign_large(t.edge_corners_, 2 * static_cast<std::size_t>(child_edges));
  tbb::parallel_for(tbb::blocked_range<Index>(0, child_edges + 1, 16384), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) t.edge_corner_offsets_[static_cast<std::size_t>(e)] = 2 * e;  // all interior
  });

  // Per parent edge: its two child faces' corner edges, and its flipped
  // edge, whose sides are corner 1 of the first child face and corner 1 of
  // the second.
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const auto sides = p.edge_corners(e);
      const Index F = face_of(sides[0]), G = face_of(sides[1]);
      // F's side runs a -> b, G's b -> a.
      const Index Fa = sides[0], Fb = next_of(sides[0]), Gb = sides[1], Ga = next_of(sides[1]);
      const Index flipped = flipped_of[static_cast<std::size_t>(e)];
      Index* c = t.corner_edge_.data() + 6 * e;
      c[0] = spoke_of[Ga], c[1] = flipped, c[2] = spoke_of[Fa];  // [V(a), F(G), F(F)]
      c[3] = spoke_of[Fb], c[4] = flipped, c[5] = spoke_of[Gb];  // [V(b), F(F), F(G)]
      t.edge_vertices_[static_cast<std::size_t>(flipped)] = {std::min(F, G), std::max(F, G)};
      t.edge_corners_[2 * static_cast<std::size_t>(flipped)] = 6 * e + 1;
      t.edge_corners_[2 * static_cast<std::size_t>(flipped) + 1] = 6 * e + 4;
    }
  });

  // A face point has 6 corners and edges, a vertex point its parent's valence.
  t.lay_out_point_split_incidence(p, 6);
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      // Around F(f): at v_i from e_i (leaving along the spoke to v_i), then at
      // v_{i+1} from e_i (leaving along e_i's flipped edge).
      Index ring_corners[6], ring_edges[6], e[3];
      bool first_side[3];  // f is e_i's F, v_i its a
      for (Index i = 0; i < 3; ++i) {
        e[i] = p.corner_edge_[3 * f + i];
        first_side[i] = p.edge_corners(e[i])[0] == 3 * f + i;
      }
      for (Index i = 0; i < 3; ++i) {
        const Index c = 3 * f + i, prev = i == 0 ? 2 : i - 1;
        ring_corners[2 * i] = 6 * e[i] + (first_side[i] ? 2 : 5);
        ring_corners[2 * i + 1] = 6 * e[i] + (first_side[i] ? 4 : 1);
        ring_edges[2 * i] = spoke_of[static_cast<std::size_t>(c)];
        ring_edges[2 * i + 1] = flipped_of[static_cast<std::size_t>(e[i])];
        // The spoke to v_i: its sides are in the child faces of e_i (leaving
        // v_i) and of e_prev (entering it: at V(b) if f is e_prev's F).
        const Index here = ring_corners[2 * i], other = 6 * e[prev] + (first_side[prev] ? 3 : 0);
        const auto spoke = static_cast<std::size_t>(ring_edges[2 * i]);
        t.edge_vertices_[spoke] = {f, vertex_point + p.corner_vertex_[c]};
        t.edge_corners_[2 * spoke] = std::min(here, other);
        t.edge_corners_[2 * spoke + 1] = std::max(here, other);
      }
      t.write_ring_from_smallest_corner(f, ring_corners, ring_edges, 6);
    }
  });
  t.derive_vertex_point_rings(p, vertex_point, 6, spoke_of);
  t.build_boundary_loops();
  return t;
}

}  // namespace subdiv
