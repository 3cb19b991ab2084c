// Interpolatory sqrt3: all of its weights (U. Labsik, G. Greiner,
// "Interpolatory sqrt(3)-subdivision", Eurographics 2000; Zorin's survey,
// section 3.1, table of schemes). The extracted survey has no weights; they
// are taken from the implementation of the paper in OpenMesh
// (InterpolatingSqrt3LGT, Sqrt3InterpolatingSubdividerLabsikGreinerT.hh), and
// checked here against what they are for (tests/rules/interpolatory_sqrt3_test.cpp):
//   vertex point  the vertex itself (the scheme interpolates);
//   face point    of a triangle whose three vertices have valence 6: the
//                 12-point rule, 32/81 on its vertices, -1/81 on the vertex
//                 opposite each edge, -2/81 on the apices of the two further
//                 triangles beyond each edge's neighbour (it reproduces cubic
//                 polynomials on a regular grid: tested);
//                 otherwise the average, over the triangle's vertices of
//                 valence k != 6, of their extraordinary rule
//                   v: 1 - a^2,  u_i: (a^2 + 2 a cos(2 pi i/k + pi/k)
//                                       + 2 a^2 cos(4 pi i/k + 2 pi/k)) / k,
//                 a = 2 cos(pi/k) / 3, and the tabulated rules for k = 3
//                 (4, -5, 4)/27 and 8/9, and k = 4 (2, -1, -1, 2)/9 and 7/9.
// The ring u_0 .. u_{k-1} starts at the face's corner before v and turns
// away from the face, so that the face lies between u_{k-1} and u_0 and the
// cosines are taken from the face's direction (angle pi/k off u_0).
//
// Boundaries (open meshes, corner tags). On the trisecting steps a boundary
// edge (v, w) gets the ternary four-point rule, the cubic through v's and
// w's boundary neighbours at a third of the way:
//   near v  20/27 v + 10/27 w - 5/81 (beyond v) - 4/81 (beyond w),
// as in OpenMesh's implementation (its compute_new_boundary_points); where
// the curve ends (a corner) the point beyond is the linear extrapolation
// 2v - w. On the other steps the paper's rules for triangles at the
// boundary appear in OpenMesh in three variants (#ifdef'd) whose published
// form could not be checked, so this project derives its own: the 12-point
// rule with the points of its stencil beyond the boundary continued
// linearly, the apex across edge (p, q) of triangle (p, q, r) taken as
// p + q - r (exact on the regular grid; linear precision). On a regular
// boundary that is 1/3, 1/3 on the boundary edge, 37/81 on the apex,
// -1/81 and -2/81 beyond (tested); the analysis finds boundary sectors of
// 1..5 faces C1. Boundary vertices count as regular (the extraordinary
// rules are for interior vertices).

#include "subdiv/rules/interpolatory_sqrt3.h"

#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include "rule_helpers.h"

namespace subdiv {

std::vector<double> interpolatory_sqrt3_weights(int k) {
  if (k == 3) return {4.0 / 27.0, -5.0 / 27.0, 4.0 / 27.0, 8.0 / 9.0};
  if (k == 4) return {2.0 / 9.0, -1.0 / 9.0, -1.0 / 9.0, 2.0 / 9.0, 7.0 / 9.0};
  const double pi = std::numbers::pi;
  const double a = 2.0 * std::cos(pi / k) / 3.0;
  std::vector<double> w(static_cast<std::size_t>(k) + 1);
  for (int i = 0; i < k; ++i)
    w[static_cast<std::size_t>(i)] =
        (a * a + 2.0 * a * std::cos(2.0 * pi * i / k + pi / k) + 2.0 * a * a * std::cos(4.0 * pi * i / k + 2.0 * pi / k)) / k;
  w[static_cast<std::size_t>(k)] = 1.0 - a * a;
  return w;
}

namespace {

// The weights of valence k, tabulated for the usual valences (a vector and
// 2k cosines per face point otherwise); the table holds the formula's own
// values. Valences past it are computed into `scratch`.
std::span<const double> extraordinary_weights(int k, std::vector<double>& scratch) {
  static const auto table = [] {
    std::array<std::vector<double>, 64> t;
    for (int j = 3; j < static_cast<int>(t.size()); ++j) t[static_cast<std::size_t>(j)] = interpolatory_sqrt3_weights(j);
    return t;
  }();
  if (k >= 3 && k < static_cast<int>(table.size())) return table[static_cast<std::size_t>(k)];
  scratch = interpolatory_sqrt3_weights(k);
  return scratch;
}

// The apex of the face across corner c's edge, or kInvalidIndex.
Index apex_across(const MeshTopology& t, Index c) {
  const Index o = t.corner_across(c);
  return o == kInvalidIndex ? kInvalidIndex : t.corner_vertex(t.corner_prev(o));
}

bool regular(const MeshTopology& t, Index v) { return t.vertex_kind(v) != VertexKind::interior || t.valence(v) == 6; }

// The 12-point rule read off the corners' one-rings, where all three are
// interior vertices of valence 6 with ordered rings (nearly every face
// after a level or two); false (and nothing added) otherwise. On the
// regular grid the rule's twelve points are exactly the three one-rings.
// Around corner vertex v, with our face as face j of its ring, face j+3 is
// the opposite face: its other two vertices are v's own points beyond
// (-2/81 each). Face j+5 shares one of v's edges with our face: its vertex
// off our face is the apex across that edge (-1/81). The rings of the three
// corners turn the same way, so the three corners name the face's three
// apices once each. This is add_regular_rule's rule; it reads each corner's
// contiguous ring instead of chasing corner_across three faces deep, which
// waits on memory. points[i] = {apex, beyond, beyond} around corner i.
bool regular_rule_points_from_rings(const MeshTopology& t, Index f, Index (&points)[3][3]) {
  const Index first = t.face_first_corner(f);
  for (Index i = 0; i < 3; ++i) {
    const Index c = first + i;
    const Index v = t.corner_vertex(c);
    const auto corners = t.vertex_corners(v);
    if (corners.size() != 6 || t.vertex_kind(v) != VertexKind::interior || !t.ring_ordered(v)) return false;
    std::size_t j = 0;
    while (corners[j] != c) ++j;
    const Index opposite = corners[(j + 3) % 6];
    points[i][1] = t.corner_vertex(t.corner_next(opposite));
    points[i][2] = t.corner_vertex(t.corner_prev(opposite));
    const Index side = corners[(j + 5) % 6];
    const Index x = t.corner_vertex(t.corner_next(side));
    const bool x_on_face = x == t.corner_vertex(t.corner_next(c)) || x == t.corner_vertex(t.corner_prev(c));
    points[i][0] = x_on_face ? t.corner_vertex(t.corner_prev(side)) : x;
  }
  return true;
}

bool add_regular_rule_from_rings(const MeshTopology& t, Index f, MaskBuilder& mask) {
  Index points[3][3];
  if (!regular_rule_points_from_rings(t, f, points)) return false;
  const Index first = t.face_first_corner(f);
  for (Index i = 0; i < 3; ++i) {
    mask.add(t.corner_vertex(first + i), 32.0 / 81.0);
    mask.add(points[i][0], -1.0 / 81.0);
    mask.add(points[i][1], -2.0 / 81.0);
    mask.add(points[i][2], -2.0 / 81.0);
  }
  return true;
}

// The 12-point rule; false (and nothing added) where a neighbour it needs
// is missing.
bool add_regular_rule(const MeshTopology& t, Index f, MaskBuilder& mask) {
  const Index first = t.face_first_corner(f);
  Index outer[9];
  for (Index i = 0; i < 3; ++i) {
    const Index o = t.corner_across(first + i);  // in the neighbour N, running against corner first + i
    if (o == kInvalidIndex) return false;
    outer[3 * i] = t.corner_vertex(t.corner_prev(o));        // N's apex
    outer[3 * i + 1] = apex_across(t, t.corner_next(o));     // beyond N's edge from our corner's end
    outer[3 * i + 2] = apex_across(t, t.corner_prev(o));     // beyond N's edge into our corner's start
    if (outer[3 * i + 1] == kInvalidIndex || outer[3 * i + 2] == kInvalidIndex) return false;
  }
  for (Index i = 0; i < 3; ++i) {
    mask.add(t.corner_vertex(first + i), 32.0 / 81.0);
    mask.add(outer[3 * i], -1.0 / 81.0);
    mask.add(outer[3 * i + 1], -2.0 / 81.0);
    mask.add(outer[3 * i + 2], -2.0 / 81.0);
  }
  return true;
}

// Vertex v's extraordinary rule for the face of corner c, weighted w.
void add_extraordinary_rule(const MeshTopology& t, Index c, double w, MaskBuilder& mask) {
  const Index v = t.corner_vertex(c);
  const auto corners = t.vertex_corners(v);
  const auto edges = t.vertex_edges(v);
  const int k = static_cast<int>(edges.size());
  int j = 0;
  while (corners[static_cast<std::size_t>(j)] != c) ++j;
  // Face j leaves v along e_j and enters along e_{j+1}: u_0 = other(e_{j+1}).
  std::vector<double> scratch;
  const std::span<const double> weights = extraordinary_weights(k, scratch);
  for (int i = 0; i < k; ++i)
    mask.add(t.other_vertex(edges[static_cast<std::size_t>((j + 1 + i) % k)], v), w * weights[static_cast<std::size_t>(i)]);
  mask.add(v, w * weights[static_cast<std::size_t>(k)]);
}

// A point of the 12-point rule's stencil: a vertex, or where the stencil
// leaves the mesh a ghost, a short combination of vertices (of at most
// four: the face's three and the apex across one of its edges).
struct StencilPoint {
  std::array<Index, 6> vertices{};
  std::array<double, 6> weights{};
  int size = 0;
};

StencilPoint vertex_point_of(Index v) {
  StencilPoint p;
  p.vertices[0] = v;
  p.weights[0] = 1.0;
  p.size = 1;
  return p;
}

// p + q - r: the apex across edge (p, q) of the triangle (p, q, r) on the
// regular grid, the mesh continued linearly past its boundary.
StencilPoint ghost_apex(const StencilPoint& p, const StencilPoint& q, const StencilPoint& r) {
  StencilPoint g;
  auto add = [&](const StencilPoint& x, double sign) {
    for (int i = 0; i < x.size; ++i) {
      int j = 0;
      while (j < g.size && g.vertices[static_cast<std::size_t>(j)] != x.vertices[static_cast<std::size_t>(i)]) ++j;
      if (j == g.size) {
        g.vertices[static_cast<std::size_t>(j)] = x.vertices[static_cast<std::size_t>(i)];
        g.weights[static_cast<std::size_t>(j)] = 0.0;
        ++g.size;
      }
      g.weights[static_cast<std::size_t>(j)] += sign * x.weights[static_cast<std::size_t>(i)];
    }
  };
  add(p, 1.0);
  add(q, 1.0);
  add(r, -1.0);
  return g;
}

void add_point(const StencilPoint& p, double w, MaskBuilder& mask) {
  for (int i = 0; i < p.size; ++i)
    mask.add(p.vertices[static_cast<std::size_t>(i)], w * p.weights[static_cast<std::size_t>(i)]);
}

// The 12-point rule next to a boundary: the stencil's points beyond the
// boundary are ghosts (ghost_apex), so the rule keeps linear precision
// there. Corner c_i of the face runs edge (v_i, v_i+1); N_i is the triangle
// across it, with apex n_i, and the rule's outer points are the apices
// across N_i's edges (v_i, n_i) and (n_i, v_i+1).
void add_regular_rule_with_ghosts(const MeshTopology& t, Index f, MaskBuilder& mask) {
  const Index first = t.face_first_corner(f);
  std::array<StencilPoint, 3> v;
  for (Index i = 0; i < 3; ++i) v[static_cast<std::size_t>(i)] = vertex_point_of(t.corner_vertex(first + i));
  for (Index i = 0; i < 3; ++i) {
    const StencilPoint& a = v[static_cast<std::size_t>(i)];
    const StencilPoint& b = v[static_cast<std::size_t>((i + 1) % 3)];
    const StencilPoint& c = v[static_cast<std::size_t>((i + 2) % 3)];
    const Index o = t.corner_across(first + i);  // in N_i, running b -> a
    const StencilPoint n = o == kInvalidIndex ? ghost_apex(a, b, c) : vertex_point_of(t.corner_vertex(t.corner_prev(o)));
    // The apex across N_i's edge from corner `corner` (p, q), opposite r.
    auto outer = [&](Index corner, const StencilPoint& p, const StencilPoint& q, const StencilPoint& r) {
      const Index apex = apex_across(t, corner);
      return apex == kInvalidIndex ? ghost_apex(p, q, r) : vertex_point_of(apex);
    };
    add_point(a, 32.0 / 81.0, mask);
    add_point(n, -1.0 / 81.0, mask);
    if (o == kInvalidIndex) {
      add_point(ghost_apex(a, n, b), -2.0 / 81.0, mask);
      add_point(ghost_apex(n, b, a), -2.0 / 81.0, mask);
    } else {
      add_point(outer(t.corner_next(o), a, n, b), -2.0 / 81.0, mask);
      add_point(outer(t.corner_prev(o), n, b, a), -2.0 / 81.0, mask);
    }
  }
}

void face_point(const LevelView& level, Index f, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  const Index first = t.face_first_corner(f);
  // Each add_regular_rule* finds all its vertices before adding any.
  if (add_regular_rule_from_rings(t, f, mask)) return;
  int irregular = 0;
  for (Index c = first; c < first + 3; ++c) irregular += !regular(t, t.corner_vertex(c));
  if (irregular == 0) {
    if (!add_regular_rule(t, f, mask)) add_regular_rule_with_ghosts(t, f, mask);
    return;
  }
  for (Index c = first; c < first + 3; ++c)
    if (!regular(t, t.corner_vertex(c))) add_extraordinary_rule(t, c, 1.0 / irregular, mask);
}

void vertex_point(const LevelView&, Index v, VertexRule, MaskBuilder& mask) { mask.add(v, 1.0); }

// The fast path: vertex points copied, face points of the 12-point rule read
// off the rings summed directly; boundary points and faces at extraordinary
// or boundary vertices take the masks.
bool evaluate_point(const LevelView& level, const SplitMap& map, Index i, std::span<const Vec3> p,
                    std::span<const Vec3>, Vec3& out) {
  auto at = [&](Index v) { return p[static_cast<std::size_t>(v)]; };
  if (i >= map.vertex_points) {
    out = at(i - map.vertex_points);
    return true;
  }
  if (i >= map.edge_points) return false;
  const MeshTopology& t = level.topology;
  const Index f = map.point_face(i - map.face_points);
  Index points[3][3];
  if (!regular_rule_points_from_rings(t, f, points)) return false;
  const Index first = t.face_first_corner(f);
  Vec3 corners, apices, beyond;
  for (Index c = 0; c < 3; ++c) {
    corners += at(t.corner_vertex(first + c));
    apices += at(points[c][0]);
    beyond += at(points[c][1]) + at(points[c][2]);
  }
  out = (32.0 / 81.0) * corners + (-1.0 / 81.0) * apices + (-2.0 / 81.0) * beyond;
  return true;
}

bool is_corner(const LevelView& level, Index v) {
  return !level.vertex_rule.empty() && level.vertex_rule[static_cast<std::size_t>(v)] == VertexRule::corner;
}

// Adds s times the boundary vertex beyond v from w along the boundary, or
// where the boundary curve ends at v (a corner) its linear extrapolation.
void add_beyond_on_boundary(const LevelView& level, Index v, Index w, double s, MaskBuilder& mask) {
  const auto [a, b] = detail::crease_neighbours(level, v);
  const Index beyond = a == w ? b : a;
  if (is_corner(level, v) || beyond == kInvalidIndex || beyond == w) {
    mask.add(v, 2.0 * s);
    mask.add(w, -s);
    return;
  }
  mask.add(beyond, s);
}

// The trisection point near v on boundary edge (v, w): the ternary
// four-point rule, the cubic through v's and w's boundary neighbours
// evaluated a third of the way from v to w.
void boundary_point(const LevelView& level, Index e, Index v, MaskBuilder& mask) {
  const Index w = level.topology.other_vertex(e, v);
  mask.add(v, 20.0 / 27.0);
  mask.add(w, 10.0 / 27.0);
  add_beyond_on_boundary(level, v, w, -5.0 / 81.0, mask);
  add_beyond_on_boundary(level, w, v, -4.0 / 81.0, mask);
}

}  // namespace

const Scheme& interpolatory_sqrt3_scheme() noexcept {
  static const Scheme scheme{
      .name = "interpolatory-sqrt3",
      .summary = "interpolating, sqrt3 split (arity sqrt 3), triangles; a 12-point rule, extraordinary rules at "
                 "valence != 6, the ternary four-point rule on boundaries",
      .citation = "U. Labsik, G. Greiner: Interpolatory sqrt(3)-subdivision, Eurographics 2000 (weights as in "
                  "OpenMesh's InterpolatingSqrt3LGT)",
      .split = SplitRule::sqrt3,
      .traits = {.interpolating = true, .needs_triangles = true, .period = 2},
      .masks = {.face_point = face_point, .vertex_point = vertex_point, .boundary_point = boundary_point},
      .fast_path = {.point = evaluate_point}};
  return scheme;
}

}  // namespace subdiv
