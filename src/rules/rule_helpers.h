#pragma once
// Small pieces shared by the rule files: the curve rules along sharp edges,
// averages over faces.

#include <cmath>
#include <numbers>

#include "subdiv/curves/curve_scheme.h"
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

/// Adds a curve mask with offsets -1, 0, 1 on the points (before, at, after).
inline void add_curve_mask(const CurveMask& curve, Index before, Index at, Index after, MaskBuilder& mask) {
  for (const CurveMaskEntry& e : curve) mask.add(e.offset < 0 ? before : e.offset > 0 ? after : at, e.weight);
}

/// The cubic B-spline curve rule at a crease or boundary vertex, its even
/// mask 1/8, 3/4, 1/8 (shared by Catmull-Clark and Loop, whose boundary
/// curve it is).
inline void add_crease_vertex(const LevelView& level, Index v, MaskBuilder& mask) {
  const auto [a, b] = crease_neighbours(level, v);
  add_curve_mask(cubic_bspline_curve_scheme().even, a, v, b, mask);
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

// Closed-form limit masks shared by Catmull-Clark and Loop: both use the
// cubic B-spline curve rules along sharp edges and keep corners.

/// Ring position of the i-th edge (face) of the sector that starts at the
/// neighbourhood's first sharp edge, wrapping around an interior ring.
inline std::size_t sector_edge(const VertexNeighbourhood& n, int i) {
  return static_cast<std::size_t>((n.sharp[0] + i) % n.edges);
}
inline std::size_t sector_face(const VertexNeighbourhood& n, int j) {
  return static_cast<std::size_t>((n.sharp[0] + j) % n.faces);
}

/// Corner: the vertex stays (limit = control point); the tangents run along
/// the two sharp edges bounding the sector. A curve whose end is kept and
/// whose next point is the edge midpoint leaves the end along (e - v): the
/// left eigenvector of eigenvalue 1/2 of its end matrix is (-1, 1, 0).
inline void corner_limit_masks(const VertexNeighbourhood& n, LimitMasks& m, int face_weights) {
  for (LimitMask* mask : {&m.position, &m.tangent1, &m.tangent2}) mask->reset(n.edges, face_weights);
  m.position.vertex = 1.0;
  m.tangent1.vertex = m.tangent2.vertex = -1.0;
  m.tangent1.edges[static_cast<std::size_t>(n.sharp[0])] = 1.0;
  m.tangent2.edges[static_cast<std::size_t>(n.sharp[1])] = 1.0;
}

/// Crease (and boundary) vertex: the limit of the cubic B-spline curve,
/// 1/6, 2/3, 1/6 (survey, section 3.2; OpenSubdiv's assignCreaseLimitMask),
/// and its derivative (e_a - e_b) / 2 along the curve, towards sharp[0]:
/// the curve scheme's limit and tangent masks, sharp[1] before the vertex
/// and sharp[0] after it. The cross tangent (tangent2) is the scheme's.
inline void crease_limit_masks(const VertexNeighbourhood& n, LimitMasks& m, int face_weights) {
  for (LimitMask* mask : {&m.position, &m.tangent1, &m.tangent2}) mask->reset(n.edges, face_weights);
  const auto a = static_cast<std::size_t>(n.sharp[0]), b = static_cast<std::size_t>(n.sharp[1]);
  const CurveScheme& curve = cubic_bspline_curve_scheme();
  const auto apply = [&](const CurveMask& weights, LimitMask& out) {
    for (const CurveMaskEntry& e : weights) (e.offset < 0 ? out.edges[b] : e.offset > 0 ? out.edges[a] : out.vertex) += e.weight;
  };
  apply(curve.limit, m.position);
  apply(curve.tangent, m.tangent1);
}

/// A sector of a single face: the cross tangent towards the mean of the two
/// edge neighbours (exact: OpenSubdiv's mask for this case, a left
/// eigenvector of the local matrix, tested).
inline void single_face_cross_tangent(const VertexNeighbourhood& n, LimitMask& t) {
  t.vertex = -1.0;
  t.edges[static_cast<std::size_t>(n.sharp[0])] = 0.5;
  t.edges[static_cast<std::size_t>(n.sharp[1])] = 0.5;
}

/// The cross tangent of a crease sector with the plain curve rules, for the
/// weights on the curve (vertex v, sharp edge neighbours a and b). Derived
/// here: the local subdivision matrix of the sector is block triangular,
///   [v a b]' = C [v a b],  interior' = X [v a b] + I interior,
/// with C the curve rules (3/4 1/8 1/8; 1/2 1/2 0; 1/2 0 1/2). A left
/// eigenvector (l_c, l_i) for mu has l_i I = mu l_i and
/// l_c (mu - C) = l_i X =: (x_v, x_a, x_b); with x_a = x_b this solves to
///   l_v = (x_v (mu - 1/2) + x_a) / ((mu - 1)(mu - 1/4)),
///   l_a = l_b = (x_a + l_v / 8) / (mu - 1/2),
/// valid for mu != 1/2 (the regular sector, where the eigenvalue is double,
/// takes the B-spline's own mask). l_i and mu are the scheme's: the interior
/// block is that of the odd modes of an interior vertex of valence 2k
/// mirrored across the crease.
inline void add_cross_tangent_curve_weights(const VertexNeighbourhood& n, double mu, double x_v, double x_a,
                                            LimitMask& t) {
  const double l_v = (x_v * (mu - 0.5) + x_a) / ((mu - 1.0) * (mu - 0.25));
  const double l_a = (x_a + l_v / 8.0) / (mu - 0.5);
  t.vertex = l_v;
  t.edges[static_cast<std::size_t>(n.sharp[0])] = l_a;
  t.edges[static_cast<std::size_t>(n.sharp[1])] = l_a;
}

/// sum_{i=1}^{k-1} sin(pi i / k) = cot(pi / (2k)).
inline double sine_sum(int k) { return 1.0 / std::tan(std::numbers::pi / (2.0 * k)); }

}  // namespace subdiv::detail
