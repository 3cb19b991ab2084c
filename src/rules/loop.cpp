// Loop: all of its weights.
//
// Source: C. Loop, "Smooth subdivision surfaces based on triangles", MS
// thesis, University of Utah, 1987; boundary rules as in Zorin's survey,
// section 3.2 (Hoppe et al. 1994):
//   edge point    3/8 (v0 + v1) + 1/8 (the two vertices opposite the edge);
//   vertex point  (1 - k beta) v + beta sum v_i over the k ring neighbours;
//   sharp or boundary edge: midpoint; crease vertex: 3/4, 1/8, 1/8; corner kept.
// Piecewise-smooth rules (survey section 3.2, after Biermann, Levin and
// Zorin 2000): next to a crease, boundary or corner vertex v, a smooth edge
// point weights v with 3/4 - gamma and the other end with gamma,
//   gamma(theta_k) = 1/2 - 1/4 cos(theta_k)
// (theta_k = pi/k at a crease vertex with k faces in the sector: gamma = 3/8
// at the regular k = 3). This makes the sector's first sine eigenvector,
// x_i = sin(i theta_k) on the ring, an eigenvector with eigenvalue
// gamma + 1/4 cos(pi/k) = 1/2, the boundary curve's own.
//
// Two named choices of beta:
//   loop         beta(k) = (1/k) (5/8 - (3/8 + 1/4 cos(2 pi / k))^2), Loop's
//                original, used by OpenSubdiv and CGAL;
//   loop-warren  beta(k) = 3/(8k) for k > 3, and 3/16 for k = 3 (J. Warren,
//                "Subdivision methods for geometric design", 1995).
//
// The survey prints 1/16 for k = 3; 3/16 is right. (1) Loop's own formula
// gives exactly 3/16 at k = 3 (cos(2 pi/3) = -1/2, so (5/8 - 1/16)/3 = 3/16),
// and Warren's rule is a simplification that keeps Loop's value where 3/(8k)
// would be poor. (2) The eigenvalues of the vertex-and-ring subdivision matrix
// are 1, 5/8 - k beta and 3/8 + 1/4 cos(2 pi j / k) (j = 1 .. k-1); C1
// continuity needs the pair 3/8 + 1/4 cos(2 pi/k) (= 1/4 at k = 3) to be
// subdominant. With beta = 3/16, 5/8 - 9/16 = 1/16 < 1/4; with beta = 1/16,
// 5/8 - 3/16 = 7/16 > 1/4 would dominate and the limit surface would not be
// tangent-plane continuous at valence-3 vertices. tests/rules/loop_test.cpp
// checks both statements numerically.

#include "subdiv/rules/loop.h"

#include <array>
#include <cmath>
#include <numbers>

#include "rule_helpers.h"

namespace subdiv {

namespace {

double loop_beta_formula(int k) {
  const double c = 0.375 + 0.25 * std::cos(2.0 * std::numbers::pi / k);
  return (0.625 - c * c) / k;
}

}  // namespace

double loop_beta(int k) noexcept {
  // Tabulated for the usual valences: a cosine per vertex was 3% of a
  // refinement. The table holds the formula's own values.
  static const auto table = [] {
    std::array<double, 64> t{};
    for (int j = 1; j < static_cast<int>(t.size()); ++j) t[static_cast<std::size_t>(j)] = loop_beta_formula(j);
    return t;
  }();
  return k > 0 && k < static_cast<int>(table.size()) ? table[static_cast<std::size_t>(k)] : loop_beta_formula(k);
}

double loop_warren_beta(int k) noexcept { return k == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * k); }

double loop_gamma(double theta) noexcept { return 0.5 - 0.25 * std::cos(theta); }

namespace {

void edge_point(const LevelView& level, Index e, EdgeRule rule, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  const auto sides = t.edge_corners(e);
  if (rule == EdgeRule::crease || sides.size() != 2) return detail::add_edge_midpoint(level, e, mask);
  const auto [a, b] = t.edge_vertices(e);
  const double shift = detail::piecewise_smooth_shift(level, e, a, b, loop_gamma);
  mask.add(a, 0.375 + shift);
  mask.add(b, 0.375 - shift);
  for (const Index c : sides) mask.add(t.corner_vertex(t.corner_prev(c)), 0.125);  // opposite vertex
}

template <double (*beta_of)(int)>
void vertex_point(const LevelView& level, Index v, VertexRule rule, MaskBuilder& mask) {
  if (detail::add_sharp_vertex(level, v, rule, mask)) return;
  const MeshTopology& t = level.topology;
  const int k = t.valence(v);
  const double beta = beta_of(k);
  mask.add(v, 1.0 - k * beta);
  for (const Index e : t.vertex_edges(v)) mask.add(t.other_vertex(e, v), beta);
}

// The fast path: smooth edge points between two triangles and smooth vertex
// points summed straight from positions, without building their masks;
// false elsewhere (boundaries, sharp and semi-sharp edges, crease and corner
// vertices), where the engine applies the masks above.
template <double (*beta_of)(int)>
bool evaluate_point(const LevelView& level, const SplitMap& map, Index i, std::span<const Vec3> p,
                    std::span<const Vec3>, Vec3& out) {
  const MeshTopology& t = level.topology;
  auto at = [&](Index v) { return p[static_cast<std::size_t>(v)]; };
  if (i < map.vertex_points) {
    const Index e = i - map.edge_points;
    const auto sides = t.edge_corners(e);
    if (sides.size() != 2 || level.is_sharp(e)) return false;
    const auto [a, b] = t.edge_vertices(e);
    const double shift = detail::piecewise_smooth_shift(level, e, a, b, loop_gamma);
    const Index c = t.corner_vertex(t.corner_prev(sides[0])), d = t.corner_vertex(t.corner_prev(sides[1]));
    out = (0.375 + shift) * at(a) + (0.375 - shift) * at(b) + 0.125 * (at(c) + at(d));
    return true;
  }
  const Index v = i - map.vertex_points;
  if (level.vertex_rule.empty() || level.vertex_rule[static_cast<std::size_t>(v)] != VertexRule::smooth) return false;
  const auto edges = t.vertex_edges(v);
  Vec3 ring;
  for (const Index e : edges) ring += at(t.other_vertex(e, v));
  const int k = static_cast<int>(edges.size());
  const double beta = beta_of(k);
  out = (1.0 - k * beta) * at(v) + beta * ring;
  return true;
}

// Closed-form limit masks (triangles: no face weights).

// Interior (smooth, dart): the limit weight chi = 8 beta / (3 + 8 k beta)
// on each neighbour, 1 - k chi on the centre (survey, section 2.2, written
// there as 1 / (3 / (8 beta) + k); OpenSubdiv's assignSmoothLimitMask), and
// the tangents sum cos(2 pi i/k) p_i, sum sin(2 pi i/k) p_i (the left
// eigenvectors of the subdominant eigenvalue 3/8 + 1/4 cos(2 pi/k), which
// do not depend on beta). k = 2 (two triangles sharing all three edges:
// the third is non-manifold, or they are a closed component): the same
// position mask, whose derivation holds there (both edges' rules read the
// other neighbour twice: e' = 3/8 v + 3/8 p_i + 1/4 p_j), and no tangents:
// the one-ring matrix has one eigenvalue per frequency after 1 (1/8 on
// p_1 - p_2, 1/64), no subdominant pair.
template <double (*beta_of)(int)>
bool smooth_limit_masks(const VertexNeighbourhood& n, LimitMasks& m) {
  const int k = n.edges;
  if (k < 2 || n.faces != k) return false;
  for (LimitMask* mask : {&m.position, &m.tangent1, &m.tangent2}) mask->reset(k, 0);
  const double beta = beta_of(k);
  const double chi = 8.0 * beta / (3.0 + 8.0 * k * beta);
  m.position.vertex = 1.0 - k * chi;
  for (int i = 0; i < k; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    const double angle = 2.0 * std::numbers::pi * i / k;
    m.position.edges[ii] = chi;
    if (k == 2) continue;
    m.tangent1.edges[ii] = std::cos(angle);
    m.tangent2.edges[ii] = std::sin(angle);
  }
  return true;
}

// The cross tangent of a crease sector of k triangles. k = 1: towards the
// two edge neighbours; k = 3 (regular): the box spline's (OpenSubdiv's
// assignCreaseLimitTangentMasks over sqrt 3). Otherwise the left eigenvector
// for mu = 3/8 + 1/4 cos(pi/k), derived in rule_helpers.h: interior weights
// sin(pi i/k) (the sine mask at valence 2k), curve coupling from the edge
// rule e_i' = 3/8 (v + e_i) + 1/8 (e_i-1 + e_i+1): x_v = 3/8 cot(pi/2k),
// x_a = x_b = sin(pi/k) / 8. (k = 2 gives e_1 - v.) OpenSubdiv uses a mask
// of the modified boundary rules (Biermann et al.) for k >= 4, which is not
// a tangent of these rules' limit surface.
void crease_cross_tangent(const VertexNeighbourhood& n, LimitMask& t) {
  const int k = n.sector_faces();
  if (k == 1) return detail::single_face_cross_tangent(n, t);
  if (k == 3) {
    t.vertex = -1.0;
    t.edges[detail::sector_edge(n, 0)] = t.edges[detail::sector_edge(n, 3)] = -0.5;
    t.edges[detail::sector_edge(n, 1)] = t.edges[detail::sector_edge(n, 2)] = 1.0;
    return;
  }
  const double angle = std::numbers::pi / k, mu = 0.375 + 0.25 * std::cos(angle);
  for (int i = 1; i < k; ++i) t.edges[detail::sector_edge(n, i)] = std::sin(i * angle);
  detail::add_cross_tangent_curve_weights(n, mu, 0.375 * detail::sine_sum(k), std::sin(angle) / 8.0, t);
}

template <double (*beta_of)(int)>
bool limit_masks(const VertexNeighbourhood& n, LimitMasks& m) {
  switch (n.rule) {
    case VertexRule::smooth:
    case VertexRule::dart: return smooth_limit_masks<beta_of>(n, m);  // darts: the smooth masks, as OpenSubdiv
    case VertexRule::crease:
      detail::crease_limit_masks(n, m, 0);
      crease_cross_tangent(n, m.tangent2);
      return true;
    case VertexRule::corner: detail::corner_limit_masks(n, m, 0); return true;
  }
  return false;
}

// At valence 6 both betas are 1/16: the quartic box spline's 5/8 and 1/16
// at a vertex, 3/8 and 1/8 at an edge.
constexpr RegularTriangleGrid kRegularGrid{.centre = 0.625, .ring = 0.0625, .near = 0.375, .far = 0.125};

}  // namespace

const Scheme& loop_scheme() {
  static const Scheme scheme{
      .name = "loop",
      .summary = "approximating, triangle split, triangle meshes; C2 quartic box spline on regular meshes; Loop's beta",
      .citation = "C. Loop: Smooth subdivision surfaces based on triangles, MS thesis, University of Utah, 1987",
      .split = SplitRule::triangle,
      .traits = {.needs_triangles = true,
                 .paper_depth_bound = PaperDepthBound::loop_theorem_3,
                 .smooth_face_varying = true,
                 .degenerate_faces = true},
      .masks = {.edge_point = edge_point, .vertex_point = vertex_point<loop_beta>,
                .boundary_curve = &cubic_bspline_curve_scheme()},
      .limit_masks = limit_masks<loop_beta>,
      .fast_path = {.point = evaluate_point<loop_beta>, .regular_triangle_grid = &kRegularGrid}};
  return scheme;
}

const Scheme& loop_warren_scheme() {
  static const Scheme scheme{
      .name = "loop-warren",
      .summary = "Loop with Warren's beta = 3/(8k) (3/16 at k = 3)",
      .citation = "J. Warren: Subdivision methods for geometric design, 1995 (unpublished manuscript), after C. Loop 1987",
      .split = SplitRule::triangle,
      .traits = {.needs_triangles = true, .smooth_face_varying = true},
      .masks = {.edge_point = edge_point, .vertex_point = vertex_point<loop_warren_beta>,
                .boundary_curve = &cubic_bspline_curve_scheme()},
      .limit_masks = limit_masks<loop_warren_beta>,
      .fast_path = {.point = evaluate_point<loop_warren_beta>, .regular_triangle_grid = &kRegularGrid}};
  return scheme;
}

}  // namespace subdiv
