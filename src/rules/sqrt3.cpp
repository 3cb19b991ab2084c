// Sqrt3: all of its weights (L. Kobbelt, "sqrt(3)-subdivision", SIGGRAPH
// 2000; Zorin's survey, section 4.2; the split is src/topology/sqrt3_split.cpp).
//   face point    the centroid of the triangle;
//   vertex point  (1 - alpha_n) v + alpha_n / n sum v_i over the n neighbours,
//                 alpha_n = (4 - 2 cos(2 pi / n)) / 9 (1/3 at n = 6).
// Kobbelt chose alpha_n so that the vertex-and-ring matrix of two steps has
// the subdominant pair of the regular case: two steps are a 1-to-9 split,
// whose regular subdominant eigenvalue is 1/3.
//
// Boundaries (Kobbelt, section 5): the boundary polygon is refined on every
// second step only (the split's alternation), by the ternary cubic B-spline
// rule, so that boundary curves are cubic B-splines. Its mask is
// (1 + z + z^2)^4 / 27 = (1, 4, 10, 16, 19, 16, 10, 4, 1) / 27 (the cubic
// B-spline's symbol, 4 factors of the ternary box (1 + z + z^2) / 3, times
// the arity 3), which gives on the trisecting steps
//   old boundary vertex     (4 v_prev + 19 v + 4 v_next) / 27,
//   new point near v on (v, w)  (v_prev + 16 v + 10 w) / 27 (v_prev: v's
//                                other boundary neighbour),
// and on the other steps boundary vertices stay where they are. These are
// the weights of Kobbelt's paper (and of OpenMesh's Sqrt3T); the
// tests/rules/sqrt3_test.cpp check them against the cubic B-spline
// evaluated at the refined parameters. A corner (VertexRule::corner) ends
// the curve as Catmull-Clark's and Loop's corners do, by the reflected
// point 2 v - w beyond it: it stays, and its new neighbour is (2 v + w) / 3.

#include "subdiv/rules/sqrt3.h"

#include <array>
#include <cmath>
#include <numbers>

#include "rule_helpers.h"

namespace subdiv {

namespace {

double sqrt3_alpha_formula(int n) { return (4.0 - 2.0 * std::cos(2.0 * std::numbers::pi / n)) / 9.0; }

}  // namespace

double sqrt3_alpha(int n) noexcept {
  // Tabulated for the usual valences (a cosine per vertex shows in profiles,
  // as for Loop's beta); the table holds the formula's own values.
  static const auto table = [] {
    std::array<double, 64> t{};
    for (int j = 1; j < static_cast<int>(t.size()); ++j) t[static_cast<std::size_t>(j)] = sqrt3_alpha_formula(j);
    return t;
  }();
  return n > 0 && n < static_cast<int>(table.size()) ? table[static_cast<std::size_t>(n)] : sqrt3_alpha_formula(n);
}

namespace {

void face_point(const LevelView& level, Index f, MaskBuilder& mask) { detail::add_face_average(level, f, 1.0, mask); }

bool is_corner(const LevelView& level, Index v) {
  return !level.vertex_rule.empty() && level.vertex_rule[static_cast<std::size_t>(v)] == VertexRule::corner;
}

void vertex_point(const LevelView& level, Index v, VertexRule rule, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  if (rule == VertexRule::corner || (rule == VertexRule::crease && !sqrt3_step_trisects(level.level))) {
    mask.add(v, 1.0);
    return;
  }
  if (rule == VertexRule::crease) {
    const auto [a, b] = detail::crease_neighbours(level, v);
    mask.add(v, 19.0 / 27.0);
    mask.add(a, 4.0 / 27.0);
    mask.add(b, 4.0 / 27.0);
    return;
  }
  const auto edges = t.vertex_edges(v);
  const int n = static_cast<int>(edges.size());
  const double alpha = sqrt3_alpha(n);
  mask.add(v, 1.0 - alpha);
  for (const Index e : edges) mask.add(t.other_vertex(e, v), alpha / n);
}

// The trisection point near v on boundary edge (v, w).
void boundary_point(const LevelView& level, Index e, Index v, MaskBuilder& mask) {
  const Index w = level.topology.other_vertex(e, v);
  const auto [a, b] = detail::crease_neighbours(level, v);
  const Index beyond = a == w ? b : a;
  if (is_corner(level, v) || beyond == kInvalidIndex) {
    mask.add(v, 2.0 / 3.0);
    mask.add(w, 1.0 / 3.0);
    return;
  }
  mask.add(beyond, 1.0 / 27.0);
  mask.add(v, 16.0 / 27.0);
  mask.add(w, 10.0 / 27.0);
}

// The fast path: face points and smooth vertex points summed directly; the
// masks on the boundary and at (semi-)sharp corners, whose rules blend.
bool evaluate_point(const LevelView& level, const SplitMap& map, Index i, std::span<const Vec3> p,
                    std::span<const Vec3>, Vec3& out) {
  const MeshTopology& t = level.topology;
  auto at = [&](Index v) { return p[static_cast<std::size_t>(v)]; };
  if (i < map.edge_points) {
    const auto corners = t.face_vertices(map.point_face(i - map.face_points));
    if (corners.size() != 3) return false;
    out = (1.0 / 3.0) * (at(corners[0]) + at(corners[1]) + at(corners[2]));
    return true;
  }
  if (i < map.vertex_points) return false;  // boundary points
  const Index v = i - map.vertex_points;
  if (level.vertex_rule.empty() || level.vertex_rule[static_cast<std::size_t>(v)] != VertexRule::smooth) return false;
  const auto edges = t.vertex_edges(v);
  const int n = static_cast<int>(edges.size());
  if (n == 0) return false;
  Vec3 sum;
  for (const Index e : edges) sum += at(t.other_vertex(e, v));
  const double alpha = sqrt3_alpha(n);
  out = (1.0 - alpha) * at(v) + (alpha / n) * sum;
  return true;
}

}  // namespace

const Scheme& sqrt3_scheme() noexcept {
  static const Scheme scheme{
      .name = "sqrt3",
      .summary = "approximating, sqrt3 split (arity sqrt 3), triangles; C2 on regular meshes, C1 at extraordinary "
                 "vertices; cubic B-spline boundaries",
      .citation = "L. Kobbelt: sqrt(3)-subdivision, SIGGRAPH 2000 (boundaries: its section 5)",
      .split = SplitRule::sqrt3,
      .traits = {.needs_triangles = true, .period = 2},  // the split turns the layout by 30 degrees on each step
      .masks = {.face_point = face_point, .vertex_point = vertex_point, .boundary_point = boundary_point},
      .fast_path = {.point = evaluate_point}};
  return scheme;
}

}  // namespace subdiv
