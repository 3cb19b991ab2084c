#pragma once
// Walking the neighbourhood of an edge or a vertex of a triangle mesh, for
// the Butterfly stencils, which reach one triangle beyond the edge's own two.

#include <optional>
#include <vector>

#include "subdiv/rules/scheme.h"

namespace subdiv::detail {

/// The vertex across edge `edge` from triangle `face`: the third vertex of
/// the edge's other triangle; kInvalidIndex when the edge has not exactly
/// two sides.
inline Index vertex_across(const MeshTopology& t, Index edge, Index face) {
  if (edge == kInvalidIndex) return kInvalidIndex;
  const auto sides = t.edge_corners(edge);
  if (sides.size() != 2) return kInvalidIndex;
  const Index other = t.corner_face(sides[0]) == face ? sides[1] : sides[0];
  return t.corner_vertex(t.corner_prev(other));
}

/// Position of edge e in v's ring, or -1.
inline int ring_position(const MeshTopology& t, Index v, Index e) {
  const auto edges = t.vertex_edges(v);
  for (std::size_t j = 0; j < edges.size(); ++j)
    if (edges[j] == e) return static_cast<int>(j);
  return -1;
}

/// Number of sharp (crease or boundary) edges at v other than `except`: the
/// smooth rule of a semi-sharp edge is evaluated while that edge is sharp,
/// and must see the neighbourhood as if it were not.
inline int sharp_edge_count(const LevelView& level, Index v, Index except = kInvalidIndex) {
  int n = 0;
  for (const Index e : level.topology.vertex_edges(v)) n += e != except && level.is_sharp(e);
  return n;
}

/// The sector of crease vertex v that holds the smooth (or semi-sharp) edge e: its ring
/// vertices from one sharp edge to the next (k + 1 of them for k faces) and
/// the position of e's other end among them. Vertex rings are ordered
/// counter-clockwise (face j between edges j and j + 1), so the sector is a
/// run of consecutive edges; nullopt when no sharp edge bounds it.
struct CreaseSector {
  std::vector<Index> ring;  ///< ring[0] and ring[k] across the sharp edges
  int position = 0;         ///< e's other end is ring[position], 0 < position < k
  int faces() const { return static_cast<int>(ring.size()) - 1; }
};

inline std::optional<CreaseSector> crease_sector(const LevelView& level, Index v, Index e) {
  const MeshTopology& t = level.topology;
  const auto edges = t.vertex_edges(v);
  const int m = static_cast<int>(edges.size());
  const int p = ring_position(t, v, e);
  if (p < 0) return std::nullopt;
  auto at = [&](int j) { return edges[static_cast<std::size_t>(((j % m) + m) % m)]; };
  auto bounds = [&](int j) { return at(j) != e && level.is_sharp(at(j)); };
  int first = p;  // walk back to the sharp edge that opens the sector
  for (int walked = 0; !bounds(first); --first)
    if (++walked > m) return std::nullopt;
  CreaseSector sector;
  for (int j = first;; ++j) {
    sector.ring.push_back(t.other_vertex(at(j), v));
    if (j > first && bounds(j)) break;
    if (j - first > m) return std::nullopt;
  }
  sector.position = p - first;
  return sector;
}

}  // namespace subdiv::detail
