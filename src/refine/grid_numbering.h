#pragma once
// The numbering of a quad-split level's descendants by index arithmetic:
// for a face of an all-quad level, the faces of the level `depth` steps
// down inside it, with their vertices numbered exactly as split_topology()
// and MeshTopology::from_quad_split() number them, and where their corners
// lie on the face's grid. No intermediate topology is built.

#include <array>
#include <cstdint>
#include <span>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"

namespace subdiv::detail {

// The element counts of an all-quad level, and of its quad split.
struct LevelCounts {
  std::int64_t faces = 0, edges = 0, vertices = 0;
  LevelCounts child() const { return {4 * faces, 2 * edges + 4 * faces, faces + edges + vertices}; }
};

// A point of a starting face's grid at the final level: x along its first
// edge, y from its first corner towards its last, both in 0 .. n.
struct GridPoint {
  int x, y;
};

inline GridPoint midpoint(GridPoint a, GridPoint b) { return {(a.x + b.x) / 2, (a.y + b.y) / 2}; }

// A face of some level inside one starting face: its number, its vertices,
// its edges (edge c runs from vertex c to vertex c + 1) and where its
// corners lie on the starting face's final grid. No member initializers:
// four are made per split, and zeroing them first costs more than the split.
struct SubFace {
  Index face;
  std::array<Index, 4> vertex, edge;
  std::array<GridPoint, 4> at;
};

// The four children of `s` in the quad split of its level (`level` its
// counts), numbered as split_topology() and MeshTopology::from_quad_split()
// number them: child face c = corner c = [vertex point of vertex c, edge
// point of edge c, face point, edge point of edge c - 1]; child vertices
// [face points | edge points | vertex points]; child edges [the interior
// edges (face point, edge point), 4 per face in the order of their parent
// edges' numbers | the halves of each parent edge, the one at its smaller
// vertex first].
// Without `edges`, the children's edges are kInvalidIndex (the last level's
// faces need none).
template <bool edges>
inline void split_sub_face(const SubFace& s, const LevelCounts& level, std::array<SubFace, 4>& children) {
  const auto edge_point = static_cast<Index>(level.faces);
  const auto vertex_point = static_cast<Index>(level.faces + level.edges);
  const auto halves = static_cast<Index>(4 * level.faces);
  auto interior = [&](Index e) {
    Index rank = 0;
    for (const Index other : s.edge) rank += other < e;
    return 4 * s.face + rank;
  };
  auto half = [&](Index e, Index end, Index other_end) { return halves + 2 * e + (end < other_end ? 0 : 1); };
  const GridPoint centre = midpoint(s.at[0], s.at[2]);
  for (int c = 0; c < 4; ++c) {
    const int next = (c + 1) % 4, prev = (c + 3) % 4;
    SubFace& child = children[static_cast<std::size_t>(c)];
    child.face = 4 * s.face + c;
    child.vertex = {vertex_point + s.vertex[c], edge_point + s.edge[c], s.face, edge_point + s.edge[prev]};
    if constexpr (edges)
      child.edge = {half(s.edge[c], s.vertex[c], s.vertex[next]), interior(s.edge[c]), interior(s.edge[prev]),
                    half(s.edge[prev], s.vertex[c], s.vertex[prev])};
    else
      child.edge = {kInvalidIndex, kInvalidIndex, kInvalidIndex, kInvalidIndex};
    child.at = {s.at[c], midpoint(s.at[c], s.at[next]), centre, midpoint(s.at[prev], s.at[c])};
  }
}

// Calls emit(sub-face) for each face of the last level inside `s`, in
// increasing order; counts[j] are the counts of the level at depth j.
template <typename Emit>
void for_each_final_face(const SubFace& s, std::size_t depth, std::span<const LevelCounts> counts, Emit& emit) {
  if (depth == counts.size()) return emit(s);
  std::array<SubFace, 4> children;
  if (depth + 1 == counts.size()) {
    split_sub_face<false>(s, counts[depth], children);
    for (const SubFace& child : children) emit(child);
    return;
  }
  split_sub_face<true>(s, counts[depth], children);
  for (const SubFace& child : children) for_each_final_face(child, depth + 1, counts, emit);
}

// A starting face as the root of its sub-faces, its corners at the grid's
// corners (0, 0), (n, 0), (n, n), (0, n).
inline SubFace root_of(const MeshTopology& t, Index f, int n) {
  SubFace s;
  s.face = f;
  const Index first = t.face_first_corner(f);
  for (int c = 0; c < 4; ++c) {
    s.vertex[c] = t.corner_vertex(first + c);
    s.edge[c] = t.corner_edge(first + c);
  }
  s.at = {GridPoint{0, 0}, GridPoint{n, 0}, GridPoint{n, n}, GridPoint{0, n}};
  return s;
}

}  // namespace subdiv::detail
