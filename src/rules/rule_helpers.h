#pragma once
// Small pieces shared by the rule files: the curve rules along sharp edges,
// averages over faces.

#include "subdiv/rules/scheme.h"

namespace subdiv::detail {

/// Adds weight w spread evenly over the vertices of face f.
inline void add_face_average(const LevelView& level, Index f, double w, MaskBuilder& mask) {
  const auto face = level.topology.face_vertices(f);
  const double each = w / static_cast<double>(face.size());
  for (const Index v : face) mask.add(v, each);
}

/// The two neighbours of v across its sharp edges (a crease vertex has
/// exactly two).
inline std::pair<Index, Index> crease_neighbours(const LevelView& level, Index v) {
  Index found[2] = {kInvalidIndex, kInvalidIndex};
  int n = 0;
  for (const Index e : level.topology.vertex_edges(v))
    if (level.is_sharp_at(e, v) && n < 2) found[n++] = level.topology.other_vertex(e, v);
  return {found[0], found[1]};
}

/// The cubic B-spline curve rule at a crease or boundary vertex:
/// 1/8, 3/4, 1/8 (shared by Catmull-Clark and Loop).
inline void add_crease_vertex(const LevelView& level, Index v, MaskBuilder& mask) {
  const auto [a, b] = crease_neighbours(level, v);
  mask.add(v, 0.75);
  mask.add(a, 0.125);
  mask.add(b, 0.125);
}

/// The rules of sharp vertices shared by Catmull-Clark and Loop: a corner
/// stays, a crease vertex follows the curve rule. False for smooth and dart
/// vertices, which the scheme's own rule handles.
inline bool add_sharp_vertex(const LevelView& level, Index v, VertexRule rule, MaskBuilder& mask) {
  if (rule == VertexRule::corner) {
    mask.add(v, 1.0);
    return true;
  }
  if (rule == VertexRule::crease) {
    add_crease_vertex(level, v, mask);
    return true;
  }
  return false;
}

/// The midpoint rule of a sharp or boundary edge.
inline void add_edge_midpoint(const LevelView& level, Index e, MaskBuilder& mask) {
  const auto [a, b] = level.topology.edge_vertices(e);
  mask.add(a, 0.5);
  mask.add(b, 0.5);
}

}  // namespace subdiv::detail
