#pragma once
// The numbering of a triangle-split level's descendants for the grid path:
// for a face of an all-triangle level, the faces of the level `depth`
// steps down inside it, with their vertices numbered exactly as
// split_topology() and MeshTopology::from_triangle_split() number them, and
// where their corners lie on the face's grid.
//
// The triangle split numbers a child's edges in (smaller end, larger end)
// order over the child's vertices [edge points | vertex points], so the
// edges whose smaller end is edge e's point are its interior edges to the
// larger edges of its faces, then its two halves. Where a child edge's
// number falls depends on how many such partners the edges before it have:
// a prefix sum over the whole level, not arithmetic within a face. The
// levels before the last two are therefore derived as TriangleLevel (face
// vertices and edges, edge sides, the prefix sums: a few numbers per face,
// no vertex incidence); the last two splits are arithmetic per face.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "grid_numbering.h"

namespace subdiv::detail {

// One level of the triangle split, enough to number its child.
struct TriangleLevel {
  Index faces = 0, edges = 0, vertices = 0;
  std::vector<std::array<Index, 3>> face_vertices, face_edges;  // edge c runs from vertex c to c + 1
  std::vector<std::array<Index, 2>> edge_faces;                 // kInvalidIndex for a boundary's missing side
  // first[e]: the child's edges before those whose smaller end is edge e's
  // point; first[edges] is the child's edge count.
  std::vector<Index> first;

  Index child_edges() const { return first.back(); }
  // The child edge from edge e's point to the point of its end `end`.
  Index half(Index e, Index end, Index other_end) const { return first[e + 1] - 2 + (end < other_end ? 0 : 1); }
  // The child edge between the points of edges a and b, sides of one face.
  Index interior(Index a, Index b) const {
    const Index lo = a < b ? a : b, hi = a < b ? b : a;
    Index rank = 0;  // lo's partners below hi: the other edges of its faces between lo and hi
    for (const Index f : edge_faces[lo])
      if (f != kInvalidIndex)
        for (const Index other : face_edges[f]) rank += other > lo && other < hi;
    return first[lo] + rank;
  }
  // Drops what only splitting needs, keeping the counts and `first`.
  void keep_counts_only();
};

// The starting level from its topology, every face a triangle and every
// edge with one or two faces; nullopt where two faces share two edges (the
// split's edges would then coincide: the generic construction's case).
std::optional<TriangleLevel> triangle_level(const MeshTopology& topology);

// The level below `parent`.
TriangleLevel child_level(const TriangleLevel& parent);

// A face of some level inside one starting face: its number, its vertices,
// its edges (kInvalidIndex where not needed) and where its corners lie on
// the starting face's final grid (corners at (0, 0), (n, 0), (0, n)).
struct SubTriangle {
  Index face;
  std::array<Index, 3> vertex, edge;
  std::array<GridPoint, 3> at;
};

// The four children of `s` (its level's edge count `edges`): child 4f + i =
// [V(v_i), E(e_i), E(e_{i-1})], 4f + 3 = [E(e_0), E(e_1), E(e_2)] with E(e)
// = e and V(v) = edges + v, their edges left unset.
inline void split_vertices(const SubTriangle& s, Index edges, std::array<SubTriangle, 4>& children) {
  for (int i = 0; i < 3; ++i) {
    const int next = (i + 1) % 3, prev = (i + 2) % 3;
    SubTriangle& child = children[static_cast<std::size_t>(i)];
    child.face = 4 * s.face + i;
    child.vertex = {edges + s.vertex[i], s.edge[i], s.edge[prev]};
    child.edge = {kInvalidIndex, kInvalidIndex, kInvalidIndex};
    child.at = {s.at[i], midpoint(s.at[i], s.at[next]), midpoint(s.at[prev], s.at[i])};
  }
  SubTriangle& centre = children[3];
  centre.face = 4 * s.face + 3;
  centre.vertex = s.edge;
  centre.edge = {kInvalidIndex, kInvalidIndex, kInvalidIndex};
  centre.at = {midpoint(s.at[0], s.at[1]), midpoint(s.at[1], s.at[2]), midpoint(s.at[2], s.at[0])};
}

// The same with the children's edges, `s` a face of `level`.
inline void split_with_edges(const SubTriangle& s, const TriangleLevel& level, std::array<SubTriangle, 4>& children) {
  split_vertices(s, level.edges, children);
  const auto& v = s.vertex;
  const auto& e = s.edge;
  for (int i = 0; i < 3; ++i) {
    const int next = (i + 1) % 3, prev = (i + 2) % 3;
    children[static_cast<std::size_t>(i)].edge = {level.half(e[i], v[i], v[next]), level.interior(e[i], e[prev]),
                                                   level.half(e[prev], v[i], v[prev])};
  }
  children[3].edge = {level.interior(e[0], e[1]), level.interior(e[1], e[2]), level.interior(e[2], e[0])};
}

// The numbering of `levels` triangle splits below a starting level.
class TriangleNumbering {
 public:
  TriangleNumbering(TriangleLevel start, int levels);

  int levels() const { return levels_; }
  // The element counts of the level at `depth` (0 .. levels).
  std::int64_t faces(int depth) const { return faces_[static_cast<std::size_t>(depth)]; }
  std::int64_t edges(int depth) const { return edges_[static_cast<std::size_t>(depth)]; }
  std::int64_t vertices(int depth) const { return vertices_[static_cast<std::size_t>(depth)]; }
  // The level at `depth` as derived (only depth 0 .. levels - 2, those
  // before the last two splits; all but the deepest keep counts only).
  const TriangleLevel& level(int depth) const { return derived_[static_cast<std::size_t>(depth)]; }
  int derived_levels() const { return static_cast<int>(derived_.size()); }

  // Calls emit(sub-triangle) for each last-level face inside starting face
  // f, in increasing order, their corners on the grid of n = 2^levels.
  template <typename Emit>
  void for_each_final_face(Index f, Emit&& emit) const;

 private:
  template <typename Emit>
  void descend(Index face, const std::array<GridPoint, 3>& at, int depth, Emit& emit) const;

  int levels_ = 0;
  std::vector<std::int64_t> faces_, edges_, vertices_;
  std::vector<TriangleLevel> derived_;
};

template <typename Emit>
void TriangleNumbering::descend(Index face, const std::array<GridPoint, 3>& at, int depth, Emit& emit) const {
  const int deepest = derived_levels() - 1;
  if (depth < deepest) {
    for (int i = 0; i < 4; ++i) {
      const int next = (i + 1) % 3, prev = (i + 2) % 3;
      const std::array<GridPoint, 3> child =
          i < 3 ? std::array<GridPoint, 3>{at[static_cast<std::size_t>(i)], midpoint(at[i], at[next]), midpoint(at[prev], at[i])}
                : std::array<GridPoint, 3>{midpoint(at[0], at[1]), midpoint(at[1], at[2]), midpoint(at[2], at[0])};
      descend(4 * face + i, child, depth + 1, emit);
    }
    return;
  }
  const TriangleLevel& level = derived_.back();
  const SubTriangle s{face, level.face_vertices[static_cast<std::size_t>(face)],
                      level.face_edges[static_cast<std::size_t>(face)], at};
  std::array<SubTriangle, 4> children, grandchildren;
  if (levels_ == 1) {
    split_vertices(s, level.edges, children);
    for (const SubTriangle& c : children) emit(c);
    return;
  }
  split_with_edges(s, level, children);
  const auto edges = static_cast<Index>(edges_[static_cast<std::size_t>(levels_ - 1)]);
  for (const SubTriangle& c : children) {
    split_vertices(c, edges, grandchildren);
    for (const SubTriangle& g : grandchildren) emit(g);
  }
}

template <typename Emit>
void TriangleNumbering::for_each_final_face(Index f, Emit&& emit) const {
  const int n = 1 << levels_;
  descend(f, {GridPoint{0, 0}, GridPoint{n, 0}, GridPoint{0, n}}, 0, emit);
}

}  // namespace subdiv::detail
