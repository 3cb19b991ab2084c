// 4-8: all of its weights (L. Velho, D. Zorin, "4-8 subdivision", CAGD 18(5),
// 2001), read on quads as the survey does (section 4.2, Figure 10): the 4-8
// mesh's diamonds are the quads, a bisection's new vertex is a face point,
// and as the edges are not refined only a face rule and a vertex rule exist.
//   face point    the average of the face's vertices;
//   vertex point  1/2 v + 1/(2k) (sum of v's k edge neighbours).
// On a regular quad mesh these are the rules of the four-direction box
// spline with every direction doubled (degree 6, C4; the survey: "C4 on
// regular grids"), derived here from its symbol: one sqrt2 step upsamples to
// the quincunx lattice and convolves with 2 cos^2(a/2) cos^2(b/2) along its
// two edge directions u, v, i.e. the mask 1/2 at the point, 1/4 at +-u, +-v
// (a new point's four old corners) and 1/8 at +-u +-v (an old vertex's edge
// neighbours); two steps give all four directions, doubled.
// tests/rules/four_eight_test.cpp checks two steps against the box spline's
// own mask, weight for weight.
//
// Extraordinary vertices: Velho and Zorin's rule for them is not in the
// survey's text and could not be recovered. A vertex of valence k != 4 takes
// the same average, 1/2 v + 1/(2k) sum; this generalisation is this
// project's, not the paper's (the analysis finds it C1 for k = 3..12).
//
// Closed meshes only (Scheme::needs_closed_mesh): at non-integer arity there
// is no natural boundary treatment (the survey, section 4.2); sharp features
// are refused as on the other non-primal splits. (Velho's Quasi 4-8 paper,
// seed 001, smooths old vertices over the new face points instead, 1/2 v +
// 1/(2k) sum of new points: on a regular grid that is 5/8, 1/16, 1/32, not
// the box spline, so it is not used.)

#include "subdiv/rules/four_eight.h"

#include "rule_helpers.h"

namespace subdiv {

namespace {

void face_point(const LevelView& level, Index f, MaskBuilder& mask) { detail::add_face_average(level, f, 1.0, mask); }

void vertex_point(const LevelView& level, Index v, VertexRule, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  const auto edges = t.vertex_edges(v);
  mask.add(v, edges.empty() ? 1.0 : 0.5);
  const double each = 0.5 / static_cast<double>(edges.size());
  for (const Index e : edges) mask.add(t.other_vertex(e, v), each);
}

}  // namespace

const Scheme& four_eight_scheme() {
  static const Scheme scheme = [] {
    Scheme s{"four-eight",
             "approximating, sqrt2 split (arity sqrt 2), closed polygon meshes; 4-8 on quads, the C4 box spline on "
             "regular meshes (extraordinary vertices: the same averaging, not the paper's rule)",
             "L. Velho, D. Zorin: 4-8 subdivision, CAGD 18(5), 2001 (regular rules from its box spline)",
             SplitRule::sqrt2,
             false,
             face_point,
             nullptr,
             vertex_point};
    s.period = 2;  // the layout turns by 45 degrees on each step
    s.needs_closed_mesh = true;
    return s;
  }();
  return scheme;
}

}  // namespace subdiv
