// Catmull-Clark: all of its weights.
//
// Source: E. Catmull and J. Clark, "Recursively generated B-spline surfaces
// on arbitrary topological meshes", CAD 10(6), 1978, in the general-polygon
// form of Zorin's survey, section 3.3:
//   face point   the centroid of the face;
//   edge point   (v0 + v1 + f0 + f1) / 4, with f0, f1 the new face points;
//   vertex point ((k-2)/k) v + (1/k^2) sum v_i + (1/k^2) sum f_i
//                (k = valence; v_i ring neighbours; f_i new face points).
// The masks weight the new face points themselves (MaskBuilder), as these
// formulas are written, rather than re-averaging each face's vertices.
// For quads this is the survey's beta = 3/(2k), gamma = 1/(4k) form, and for
// k = 4 the bicubic B-spline rules.
// Sharp and boundary edges use the cubic B-spline curve rules: edge midpoint,
// and 3/4, 1/8, 1/8 at crease vertices; corners are kept; darts use the
// smooth rule; semi-sharp features blend these (refine/creasing.cpp). This is
// OpenSubdiv's Sdc::Scheme<SCHEME_CATMARK>.
// Piecewise-smooth rules (survey section 3.3, after Biermann, Levin and
// Zorin 2000): next to a crease, boundary or corner vertex v, a smooth edge
// point weights v with 3/4 - gamma and the other end with gamma (1/16 on the
// four other vertices of its two quads), gamma(theta_k) = 3/8 - 1/4
// cos(theta_k); the regular boundary (k = 2, theta = pi/2) keeps 3/8, 3/8.
// In the face-point form below, the ends' 1/4 each move by the same amount.

#include "subdiv/rules/catmull_clark.h"

#include <cmath>

#include "rule_helpers.h"

namespace subdiv {

namespace {

double gamma_of(double theta) { return catmull_clark_gamma(theta); }

void face_point(const LevelView& level, Index f, MaskBuilder& mask) { detail::add_face_average(level, f, 1.0, mask); }

void edge_point(const LevelView& level, Index e, EdgeRule rule, MaskBuilder& mask) {
  const auto sides = level.topology.edge_corners(e);
  if (rule == EdgeRule::crease || sides.size() != 2) return detail::add_edge_midpoint(level, e, mask);
  const auto [a, b] = level.topology.edge_vertices(e);
  const double shift = detail::piecewise_smooth_shift(level, e, a, b, gamma_of);
  mask.add(a, 0.25 + shift);
  mask.add(b, 0.25 - shift);
  for (const Index c : sides) mask.add_face_point(level.topology.corner_face(c), 0.25);
}

void vertex_point(const LevelView& level, Index v, VertexRule rule, MaskBuilder& mask) {
  if (detail::add_sharp_vertex(level, v, rule, mask)) return;
  const MeshTopology& t = level.topology;
  const double k = t.valence(v);
  const double k2 = k * k;
  mask.add(v, (k - 2.0) / k);
  for (const Index e : t.vertex_edges(v)) mask.add(t.other_vertex(e, v), 1.0 / k2);
  for (const Index c : t.vertex_corners(v)) mask.add_face_point(t.corner_face(c), 1.0 / k2);
}

}  // namespace

double catmull_clark_gamma(double theta) { return 0.375 - 0.25 * std::cos(theta); }

const Scheme& catmull_clark_scheme() {
  static const Scheme scheme{
      "catmull-clark",
      "approximating, quad split, any polygon mesh; C2 bicubic B-spline on regular quads, C1 elsewhere",
      "E. Catmull, J. Clark: Recursively generated B-spline surfaces on arbitrary topological meshes, CAD 10(6), 1978",
      SplitRule::quad, false, face_point, edge_point, vertex_point};
  return scheme;
}

}  // namespace subdiv
