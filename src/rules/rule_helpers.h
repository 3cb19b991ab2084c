#pragma once
// Small pieces shared by the rule files: the curve rules along sharp edges,
// averages over faces.

#include <cmath>

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
    if (level.is_sharp(e) && n < 2) found[n++] = level.topology.other_vertex(e, v);
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

/// Piecewise-smooth rules: theta_k = alpha / k for the sector of vertex v
/// that holds the smooth edge e, k the faces between the sharp edges that
/// bound it; 0 when v has no sector angle (a smooth vertex, or the standard
/// rules). Vertex rings are ordered: face j lies between edges j and j + 1.
inline double sector_theta(const LevelView& level, Index v, Index e) {
  if (level.sector_angle.empty()) return 0.0;
  const double alpha = level.sector_angle[static_cast<std::size_t>(v)];
  if (alpha <= 0.0) return 0.0;
  const auto edges = level.topology.vertex_edges(v);
  const auto m = static_cast<int>(edges.size());
  int j = 0;
  while (j < m && edges[static_cast<std::size_t>(j)] != e) ++j;
  if (j == m) return 0.0;
  int k = 0;
  for (const int step : {1, m - 1}) {  // forwards, then backwards
    for (int i = j, walked = 0;; ++walked) {
      if (walked == m) return 0.0;  // no sharp edge bounds the sector
      ++k;
      i = (i + step) % m;
      if (level.is_sharp(edges[static_cast<std::size_t>(i)])) break;
    }
  }
  return alpha / k;
}

/// The weight the piecewise-smooth rules move onto end a of the smooth edge
/// e = (a, b), and off end b (Biermann, Levin and Zorin 2000): next to a
/// vertex v with a sector angle the edge point weights v with 3/4 - gamma
/// and the other end with gamma, where the standard rule has 3/8 and 3/8, so
/// v gains 3/8 - gamma(theta_k). When both ends have a sector angle the two
/// shifts are averaged. `gamma` is the scheme's gamma(theta).
template <typename Gamma>
double piecewise_smooth_shift(const LevelView& level, Index e, Index a, Index b, Gamma gamma) {
  // At the regular sector gamma is 3/8 up to the rounding of cos (cos(pi/3)
  // is 0.5000000000000001): shifts that small are the regular case, made
  // exact so that regular boundaries keep the standard rule bit for bit.
  // The smallest genuine shift is 0.05 (Loop, k = 4).
  auto shift_at = [&](double theta) {
    if (theta <= 0.0) return 0.0;
    const double shift = 0.375 - gamma(theta);
    return std::fabs(shift) < 1e-12 ? 0.0 : shift;
  };
  const double ta = sector_theta(level, a, e), tb = sector_theta(level, b, e);
  const double shift_a = shift_at(ta), shift_b = shift_at(tb);
  if (ta > 0.0 && tb > 0.0) return 0.5 * (shift_a - shift_b);
  return shift_a - shift_b;
}

/// The midpoint rule of a sharp or boundary edge.
inline void add_edge_midpoint(const LevelView& level, Index e, MaskBuilder& mask) {
  const auto [a, b] = level.topology.edge_vertices(e);
  mask.add(a, 0.5);
  mask.add(b, 0.5);
}

}  // namespace subdiv::detail
