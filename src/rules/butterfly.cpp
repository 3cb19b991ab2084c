// The Butterfly schemes: all of their weights. Both interpolate: a vertex
// point is its parent vertex (weight 1), and only edge points are computed.
//
// butterfly (N. Dyn, D. Levin, J. A. Gregory, "A butterfly subdivision
// scheme for surface interpolation with tension control", ACM TOG 9(2),
// 1990): the edge point of edge (a, b) with opposite vertices c, d and the
// four "wing" vertices e1..e4 across the other edges of the two triangles is
//   1/2 (a + b) + 2w (c + d) - w (e1 + e2 + e3 + e4),
// at every valence, with tension w (SchemeParameters::tension; 1/16, the
// default, gives cubic precision on regular meshes). The rule needs both triangles and all four wings; where the
// stencil is cut by a boundary or a crease, and along creases, the modified
// Butterfly's rules below are used (the 1990 paper has no boundary rules).
//
// modified-butterfly (D. Zorin, P. Schroeder, W. Sweldens, "Interpolating
// subdivision for meshes with arbitrary topology", SIGGRAPH 1996; boundary
// rules from Zorin's survey "Subdivision on arbitrary meshes", section 4):
//   regular interior (both ends of valence 6): the 8-point rule, w = 1/16
//     (the paper's 10-point stencil with its extra weight set to 0);
//   an extraordinary interior end of valence k: 3/4 on it and s_j on its
//     ring, j counted from the edge's other end,
//       s_j = (1/k) (1/4 + cos(2 pi j/k) + 1/2 cos(4 pi j/k))   (k >= 5),
//       k = 3: 5/12, -1/12, -1/12;  k = 4: 3/8, 0, -1/8, 0;
//   an extraordinary crease end with k faces in the edge's sector
//     (theta = pi/k, edge i of the sector counted from a sharp edge):
//       c_i     = 1 - (1/k) sin(theta) sin(i theta) / (1 - cos theta)  (centre)
//       c_i0 = -c_ik = 1/4 cos(i theta)
//                      - (1/4k) sin(2 theta) sin(2 i theta) / (cos theta - cos 2 theta)
//       c_ij    = (1/k) (sin(i theta) sin(j theta) + 1/2 sin(2 i theta) sin(2 j theta));
//   both ends extraordinary: the average of their two rules; one end
//     extraordinary: its rule alone (the survey's head/tail table);
//   a crease or boundary edge: the four-point rule -1/16, 9/16, 9/16, -1/16
//     along the crease (Dyn, Levin, Gregory 1987).
// A vertex is "regular" with valence 6 inside and 3 faces on a crease.
//
// Documented departures, where the survey's masks were in a figure lost from
// its text: (1) the regular interior-crease and crease-crease rules (both
// ends regular, at least one on a crease) use the extraordinary crease rule
// at k = 3 from each crease end (averaged over the two ends when both are on
// a crease); that rule is the survey's own formula, defined at every k.
// (2) At the end of a crease (a corner, a dart, or a vertex with more than
// two sharp edges) the four-point rule has no point beyond that end; it is
// replaced by the quadratic extrapolation p(-1) = 3 p(0) - 3 p(1) + p(2),
// which gives 3/8, 3/4, -1/8 (the quadratic through the three points). A
// corner's sector takes the crease rule. Vertices whose ring is not ordered
// (non-manifold) and interior vertices of valence < 3 make their edges'
// points midpoints.
//
// Every statement here is checked in tests/rules/butterfly_test.cpp.

#include "subdiv/rules/butterfly.h"

#include <cmath>
#include <numbers>

#include "rule_helpers.h"
#include "triangle_ring.h"

namespace subdiv {

double modified_butterfly_interior_weight(int k, int j) noexcept {
  if (k == 3) return j == 0 ? 5.0 / 12.0 : -1.0 / 12.0;
  if (k == 4) return j == 0 ? 3.0 / 8.0 : j == 2 ? -1.0 / 8.0 : 0.0;
  const double angle = 2.0 * std::numbers::pi * j / k;
  return (0.25 + std::cos(angle) + 0.5 * std::cos(2.0 * angle)) / k;
}

double modified_butterfly_crease_weight(int k, int i, int j) noexcept {
  const double theta = std::numbers::pi / k;
  if (j == 0 || j == k) {
    const double c_i0 = 0.25 * std::cos(i * theta) - std::sin(2.0 * theta) * std::sin(2.0 * i * theta) /
                                                          (4.0 * k * (std::cos(theta) - std::cos(2.0 * theta)));
    return j == 0 ? c_i0 : -c_i0;
  }
  return (std::sin(i * theta) * std::sin(j * theta) +
          0.5 * std::sin(2.0 * i * theta) * std::sin(2.0 * j * theta)) / k;
}

double modified_butterfly_crease_centre_weight(int k, int i) noexcept {
  const double theta = std::numbers::pi / k;
  return 1.0 - std::sin(theta) * std::sin(i * theta) / (k * (1.0 - std::cos(theta)));
}

namespace {

// The kinds of edge ends the modified Butterfly tells apart.
enum class End { regular_interior, extraordinary_interior, regular_crease, extraordinary_crease, unsupported };

End classify_end(const LevelView& level, Index v, Index e) {
  const MeshTopology& t = level.topology;
  if (!t.ring_ordered(v)) return End::unsupported;
  // Darts (one sharp edge) take the interior rule, as in the survey's
  // section 3.2; two or more sharp edges bound sectors.
  if (detail::sharp_edge_count(level, v, e) < 2) {
    if (t.vertex_kind(v) != VertexKind::interior || t.valence(v) < 3) return End::unsupported;
    return t.valence(v) == 6 ? End::regular_interior : End::extraordinary_interior;
  }
  const auto sector = detail::crease_sector(level, v, e);
  if (!sector) return End::unsupported;
  return sector->faces() == 3 ? End::regular_crease : End::extraordinary_crease;
}

// 3/4 on v, s_j on its ring from the edge's other end (j = 0) on.
void add_interior_rule(const LevelView& level, Index v, Index e, double scale, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  const auto edges = t.vertex_edges(v);
  const int k = static_cast<int>(edges.size());
  const int p = detail::ring_position(t, v, e);
  mask.add(v, 0.75 * scale);
  for (int j = 0; j < k; ++j)
    mask.add(t.other_vertex(edges[static_cast<std::size_t>((p + j) % k)], v),
             scale * modified_butterfly_interior_weight(k, j));
}

// c_i on v, c_ij on the ring of the sector that holds e.
void add_crease_rule(const LevelView& level, Index v, Index e, double scale, MaskBuilder& mask) {
  const detail::CreaseSector sector = *detail::crease_sector(level, v, e);
  const int k = sector.faces(), i = sector.position;
  mask.add(v, scale * modified_butterfly_crease_centre_weight(k, i));
  for (int j = 0; j <= k; ++j)
    mask.add(sector.ring[static_cast<std::size_t>(j)], scale * modified_butterfly_crease_weight(k, i, j));
}

void add_end_rule(const LevelView& level, Index v, Index e, End end, double scale, MaskBuilder& mask) {
  if (end == End::regular_interior || end == End::extraordinary_interior)
    return add_interior_rule(level, v, e, scale, mask);
  add_crease_rule(level, v, e, scale, mask);
}

// The 8-point rule, or false (nothing added) when a triangle or a wing is
// missing. A wing across a sharp edge is used: both ends of that edge are
// then darts or smooth, which take the smooth rule.
bool add_eight_point(const LevelView& level, Index e, double w, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  const auto sides = t.edge_corners(e);
  if (sides.size() != 2) return false;
  Index opposite[2], wing[4];
  for (int s = 0; s < 2; ++s) {
    const Index c = sides[static_cast<std::size_t>(s)];
    const Index face = t.corner_face(c);
    opposite[s] = t.corner_vertex(t.corner_prev(c));
    int n = 2 * s;
    for (const Index edge : {t.corner_edge(t.corner_next(c)), t.corner_edge(t.corner_prev(c))}) {
      wing[n] = detail::vertex_across(t, edge, face);
      if (wing[n++] == kInvalidIndex) return false;
    }
  }
  const auto [a, b] = t.edge_vertices(e);
  mask.add(a, 0.5);
  mask.add(b, 0.5);
  for (const Index c : opposite) mask.add(c, 2.0 * w);
  for (const Index x : wing) mask.add(x, -w);
  return true;
}

// The other neighbour of v along the crease through edge e, or kInvalidIndex
// when v does not continue the crease (exactly two sharp edges).
Index crease_continuation(const LevelView& level, Index v, Index e) {
  if (detail::sharp_edge_count(level, v) != 2) return kInvalidIndex;
  for (const Index other : level.topology.vertex_edges(v))
    if (other != e && level.is_sharp(other)) return level.topology.other_vertex(other, v);
  return kInvalidIndex;
}

// The four-point rule along a crease or boundary (Dyn, Levin, Gregory 1987),
// with the quadratic end rule where the crease stops.
void crease_edge_point(const LevelView& level, Index e, MaskBuilder& mask) {
  const auto [a, b] = level.topology.edge_vertices(e);
  const Index before = crease_continuation(level, a, e), after = crease_continuation(level, b, e);
  if (before != kInvalidIndex && after != kInvalidIndex) {
    mask.add(before, -1.0 / 16.0);
    mask.add(a, 9.0 / 16.0);
    mask.add(b, 9.0 / 16.0);
    mask.add(after, -1.0 / 16.0);
  } else if (before != kInvalidIndex || after != kInvalidIndex) {
    const bool a_is_end = before == kInvalidIndex;
    mask.add(a_is_end ? a : b, 3.0 / 8.0);
    mask.add(a_is_end ? b : a, 3.0 / 4.0);
    mask.add(a_is_end ? after : before, -1.0 / 8.0);
  } else {
    detail::add_edge_midpoint(level, e, mask);
  }
}

void modified_edge_point(const LevelView& level, Index e, MaskBuilder& mask) {
  const auto [a, b] = level.topology.edge_vertices(e);
  const End ea = classify_end(level, a, e), eb = classify_end(level, b, e);
  if (ea == End::unsupported || eb == End::unsupported) return detail::add_edge_midpoint(level, e, mask);
  if (ea == End::regular_interior && eb == End::regular_interior &&
      add_eight_point(level, e, kButterflyTension, mask))
    return;
  auto extraordinary = [](End x) { return x == End::extraordinary_interior || x == End::extraordinary_crease; };
  auto crease = [](End x) { return x == End::regular_crease || x == End::extraordinary_crease; };
  // Which ends' rules apply: the extraordinary ones if any, else (departure
  // (1) above) the crease ones; both are averaged.
  bool use_a = extraordinary(ea), use_b = extraordinary(eb);
  if (!use_a && !use_b) {
    use_a = crease(ea);
    use_b = crease(eb);
  }
  if (!use_a && !use_b) return detail::add_edge_midpoint(level, e, mask);  // regular, stencil cut
  const double scale = use_a && use_b ? 0.5 : 1.0;
  if (use_a) add_end_rule(level, a, e, ea, scale, mask);
  if (use_b) add_end_rule(level, b, e, eb, scale, mask);
}

void modified_butterfly_edge_point(const LevelView& level, Index e, EdgeRule rule, MaskBuilder& mask) {
  if (rule == EdgeRule::crease || level.topology.edge_face_count(e) != 2) return crease_edge_point(level, e, mask);
  modified_edge_point(level, e, mask);
}

// The original rule wherever its stencil is whole and lies off creases.
void butterfly_edge_point(const LevelView& level, Index e, EdgeRule rule, MaskBuilder& mask) {
  if (rule == EdgeRule::crease || level.topology.edge_face_count(e) != 2) return crease_edge_point(level, e, mask);
  const auto [a, b] = level.topology.edge_vertices(e);
  const bool on_crease = detail::sharp_edge_count(level, a, e) >= 2 || detail::sharp_edge_count(level, b, e) >= 2;
  if (!on_crease && add_eight_point(level, e, level.tension(), mask)) return;
  modified_edge_point(level, e, mask);
}

void interpolating_vertex_point(const LevelView&, Index v, VertexRule, MaskBuilder& mask) { mask.add(v, 1.0); }

// On regular triangles (both ends of every edge interior of valence 6,
// no sharp edge) both schemes are the 8-point rule: old points stay; an
// edge point is 1/2 on the ends, 2w on the opposite vertices and -w on the
// wings (the modified Butterfly's w is 1/16).
std::optional<RegularTriangleGrid> eight_point_grid(const SchemeParameters& parameters) {
  const double w = std::get<TensionParameters>(parameters).tension;
  return RegularTriangleGrid{.centre = 1.0, .ring = 0.0, .near = 0.5, .far = 2 * w, .wing = -w};
}
constexpr RegularTriangleGrid kModifiedRegularGrid{
    .centre = 1.0, .ring = 0.0, .near = 0.5, .far = 2 * kButterflyTension, .wing = -kButterflyTension};

}  // namespace

const Scheme& butterfly_scheme() noexcept {
  static const Scheme scheme{
      .name = "butterfly",
      .summary = "interpolating, triangle split, triangle meshes; the 8-point rule, tension w (default 1/16); C1 on regular meshes",
      .citation = "N. Dyn, D. Levin, J. A. Gregory: A butterfly subdivision scheme for surface interpolation with tension "
      "control, ACM Transactions on Graphics 9(2), 1990",
      .split = SplitRule::triangle,
      .traits = {.interpolating = true, .needs_triangles = true},
      .masks = {.edge_point = butterfly_edge_point, .vertex_point = interpolating_vertex_point},
      .fast_path = {.regular_triangle_grid_of = eight_point_grid},
      .parameters = TensionParameters{kButterflyTension}};
  return scheme;
}

const Scheme& modified_butterfly_scheme() noexcept {
  static const Scheme scheme{
      .name = "modified-butterfly",
      .summary = "interpolating, triangle split, triangle meshes; Butterfly with rules for extraordinary and crease vertices",
      .citation = "D. Zorin, P. Schroeder, W. Sweldens: Interpolating subdivision for meshes with arbitrary topology, "
      "SIGGRAPH 1996; boundary rules from D. Zorin's survey, section 4",
      .split = SplitRule::triangle,
      .traits = {.interpolating = true, .needs_triangles = true},
      .masks = {.edge_point = modified_butterfly_edge_point, .vertex_point = interpolating_vertex_point},
      .fast_path = {.regular_triangle_grid = &kModifiedRegularGrid}};
  return scheme;
}

}  // namespace subdiv
