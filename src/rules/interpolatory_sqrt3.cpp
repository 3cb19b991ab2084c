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
// Closed meshes only (Scheme::needs_closed_mesh): the paper's boundary
// rules are not implemented. Its trisecting boundary rule is the ternary
// four-point rule, but the rules for boundary triangles on the other steps
// appear in OpenMesh in alternative variants whose published form could not
// be checked. (In the analysis' ring meshes, whose outer boundary lies
// outside the neighbourhood read, faces without the rule's neighbours take
// their centroid and boundary points their edge's thirds.)

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

void face_point(const LevelView& level, Index f, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  const Index first = t.face_first_corner(f);
  int irregular = 0;
  for (Index c = first; c < first + 3; ++c) irregular += !regular(t, t.corner_vertex(c));
  if (irregular == 0) {
    // add_regular_rule finds all its vertices before adding any.
    if (!add_regular_rule(t, f, mask)) detail::add_face_average(level, f, 1.0, mask);  // the analysis ring's rim
    return;
  }
  for (Index c = first; c < first + 3; ++c)
    if (!regular(t, t.corner_vertex(c))) add_extraordinary_rule(t, c, 1.0 / irregular, mask);
}

void vertex_point(const LevelView&, Index v, VertexRule, MaskBuilder& mask) { mask.add(v, 1.0); }

void boundary_point(const LevelView& level, Index e, Index v, MaskBuilder& mask) {
  mask.add(v, 2.0 / 3.0);
  mask.add(level.topology.other_vertex(e, v), 1.0 / 3.0);
}

}  // namespace

const Scheme& interpolatory_sqrt3_scheme() {
  static const Scheme scheme = [] {
    Scheme s{"interpolatory-sqrt3",
             "interpolating, sqrt3 split (arity sqrt 3), closed triangle meshes; a 12-point rule, extraordinary "
             "rules at valence != 6",
             "U. Labsik, G. Greiner: Interpolatory sqrt(3)-subdivision, Eurographics 2000 (weights as in OpenMesh's "
             "InterpolatingSqrt3LGT)",
             SplitRule::sqrt3,
             true,
             face_point,
             nullptr,
             vertex_point};
    s.boundary_point = boundary_point;
    s.period = 2;
    s.needs_closed_mesh = true;
    return s;
  }();
  return scheme;
}

}  // namespace subdiv
