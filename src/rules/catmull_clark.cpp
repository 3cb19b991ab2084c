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
// OpenSubdiv's smooth triangle rule (the `smoothtriangles smooth` tag,
// Sdc::Options::TRI_SUB_SMOOTH; Sdc::Scheme<SCHEME_CATMARK>::
// assignSmoothMaskForEdge, after Hbr): a smooth edge between two faces, one
// or both of them triangles, weights each face point with
// w = (w0 + w1) / 2, w_i = 0.47 for a triangle and 1/4 otherwise, and each
// end with (1 - 2w) / 2. Refined levels have no triangles.

#include "subdiv/rules/catmull_clark.h"

#include <cmath>
#include <numbers>
#include <span>

#include "rule_helpers.h"

namespace subdiv {

namespace {

double gamma_of(double theta) { return catmull_clark_gamma(theta); }

void face_point(const LevelView& level, Index f, MaskBuilder& mask) { detail::add_face_average(level, f, 1.0, mask); }

// The weight of each of a smooth edge's two face points.
double edge_face_weight(const LevelView& level, std::span<const Index> sides) {
  if (level.triangle_subdivision != TriangleSubdivision::smooth) return 0.25;
  constexpr double kTriangleWeight = 0.47;  // OpenSubdiv's CATMARK_SMOOTH_TRI_EDGE_WEIGHT
  double sum = 0.0;
  for (const Index c : sides)
    sum += level.topology.face_size(level.topology.corner_face(c)) == 3 ? kTriangleWeight : 0.25;
  return sum / 2.0;
}

void edge_point(const LevelView& level, Index e, EdgeRule rule, MaskBuilder& mask) {
  const auto sides = level.topology.edge_corners(e);
  if (rule == EdgeRule::crease || sides.size() != 2) return detail::add_edge_midpoint(level, e, mask);
  const auto [a, b] = level.topology.edge_vertices(e);
  const double shift = detail::piecewise_smooth_shift(level, e, a, b, gamma_of);
  const double face_weight = edge_face_weight(level, sides);
  const double end_weight = (1.0 - 2.0 * face_weight) / 2.0;
  mask.add(a, end_weight + shift);
  mask.add(b, end_weight - shift);
  for (const Index c : sides) mask.add_face_point(level.topology.corner_face(c), face_weight);
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

// Closed-form limit masks (faces are quads; face weights sit on each face's
// vertex opposite the centre).

// The subdominant eigenvalue at an interior vertex of valence k (Halstead,
// Kass and DeRose 1993, appendix; OpenSubdiv's catmarkScheme.h):
// (5 + cos(2 pi/k) + cos(pi/k) sqrt(2 (9 + cos(2 pi/k)))) / 16 = (A_k + 4) / 16.
double subdominant_eigenvalue(int k) {
  const double c = std::cos(2.0 * std::numbers::pi / k);
  return (5.0 + c + std::cos(std::numbers::pi / k) * std::sqrt(2.0 * (9.0 + c))) / 16.0;
}

// Interior (smooth, dart): position k^2 : 4 : 1 over k (k + 5) on centre,
// edge and face neighbours (survey, section 2.2; OpenSubdiv's
// assignSmoothLimitMask). Tangents: Halstead, Kass and DeRose, "Efficient,
// fair interpolation using Catmull-Clark surfaces", SIGGRAPH 1993: edge
// weights A_k cos(2 pi i/k), face weights cos(2 pi i/k) + cos(2 pi (i+1)/k),
// A_k = 1 + cos(2 pi/k) + cos(pi/k) sqrt(2 (9 + cos(2 pi/k))); sines for the
// second. OpenSubdiv's masks are these times 4 / A_k.
bool smooth_limit_masks(const VertexNeighbourhood& n, LimitMasks& m) {
  const int k = n.faces;
  if (k < 3 || n.edges != k) return false;
  for (LimitMask* mask : {&m.position, &m.tangent1, &m.tangent2}) mask->reset(k, k);
  const double denominator = k * (k + 5.0);
  m.position.vertex = k * k / denominator;
  const double a = 16.0 * subdominant_eigenvalue(k) - 4.0;
  for (int i = 0; i < k; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    const double t0 = 2.0 * std::numbers::pi * i / k, t1 = 2.0 * std::numbers::pi * (i + 1) / k;
    m.position.edges[ii] = 4.0 / denominator;
    m.position.faces[ii] = 1.0 / denominator;
    m.tangent1.edges[ii] = a * std::cos(t0);
    m.tangent1.faces[ii] = std::cos(t0) + std::cos(t1);
    m.tangent2.edges[ii] = a * std::sin(t0);
    m.tangent2.faces[ii] = std::sin(t0) + std::sin(t1);
  }
  return true;
}

// The cross tangent of a crease sector of k faces. k = 1: towards the two
// edge neighbours; k = 2 (regular): the bicubic B-spline's cross derivative
// (OpenSubdiv's assignCreaseLimitTangentMasks, times 6). k >= 3: the left
// eigenvector for mu = lambda(2k), derived in rule_helpers.h: interior
// weights are the sine mask of Halstead et al. at valence 2k (edges
// A sin(pi i/k), faces sin(pi j/k) + sin(pi (j+1)/k)); the curve coupling
// l_i X has x_v = cot(pi/2k) (3A/8 + 1/2) = cot(pi/2k) (6 mu - 1) and
// x_a = x_b = sin(pi/k) (A/16 + 1/4) = mu sin(pi/k), from the edge rule
// e_i' = 3/8 (v + e_i) + 1/16 (e_i-1 + e_i+1 + f_i-1 + f_i) and the face
// rule f_j' = (v + e_j + f_j + e_j+1) / 4. OpenSubdiv uses Biermann et al.'s
// mask instead, which belongs to their modified boundary rules: for k >= 3
// it is not a tangent of these rules' limit surface.
void crease_cross_tangent(const VertexNeighbourhood& n, LimitMask& t) {
  const int k = n.sector_faces();
  if (k == 1) return detail::single_face_cross_tangent(n, t);
  if (k == 2) {
    t.vertex = -4.0;
    t.edges[detail::sector_edge(n, 0)] = t.edges[detail::sector_edge(n, 2)] = -1.0;
    t.edges[detail::sector_edge(n, 1)] = 4.0;
    t.faces[detail::sector_face(n, 0)] = t.faces[detail::sector_face(n, 1)] = 1.0;
    return;
  }
  const double mu = subdominant_eigenvalue(2 * k), a = 16.0 * mu - 4.0, angle = std::numbers::pi / k;
  for (int i = 1; i < k; ++i) t.edges[detail::sector_edge(n, i)] = a * std::sin(i * angle);
  for (int j = 0; j < k; ++j) t.faces[detail::sector_face(n, j)] = std::sin(j * angle) + std::sin((j + 1) * angle);
  detail::add_cross_tangent_curve_weights(n, mu, detail::sine_sum(k) * (6.0 * mu - 1.0), mu * std::sin(angle), t);
}

bool limit_masks(const VertexNeighbourhood& n, LimitMasks& m) {
  switch (n.rule) {
    case VertexRule::smooth:
    case VertexRule::dart: return smooth_limit_masks(n, m);  // darts: the smooth masks, as OpenSubdiv
    case VertexRule::crease:
      detail::crease_limit_masks(n, m, n.faces);
      crease_cross_tangent(n, m.tangent2);
      return true;
    case VertexRule::corner: detail::corner_limit_masks(n, m, n.faces); return true;
  }
  return false;
}

// On regular quads the rules above are the uniform cubic B-spline's
// refinement along each grid line: 1/8, 3/4, 1/8 at old points, 1/2, 1/2 at
// new ones (Lane and Riesenfeld 1980).
constexpr RegularGrid kRegularGrid{.even = {0.0, 0.125, 0.75, 0.125, 0.0}, .odd = {0.0, 0.5, 0.5, 0.0}};

}  // namespace

double catmull_clark_gamma(double theta) noexcept { return 0.375 - 0.25 * std::cos(theta); }
double catmull_clark_subdominant_eigenvalue(int valence) noexcept { return subdominant_eigenvalue(valence); }

const Scheme& catmull_clark_scheme() {
  static const Scheme scheme{
      .name = "catmull-clark",
      .summary = "approximating, quad split, any polygon mesh; C2 bicubic B-spline on regular quads, C1 elsewhere",
      .citation = "E. Catmull, J. Clark: Recursively generated B-spline surfaces on arbitrary topological meshes, CAD 10(6), 1978",
      .split = SplitRule::quad,
      .traits = {.paper_depth_bound = PaperDepthBound::cheng_catmull_clark,
                 .smooth_face_varying = true,
                 .degenerate_faces = true},
      .masks = {.face_point = face_point, .edge_point = edge_point, .vertex_point = vertex_point,
                .boundary_curve = &cubic_bspline_curve_scheme()},
      .limit_masks = limit_masks,
      .fast_path = {.regular_grid = &kRegularGrid}};
  return scheme;
}

}  // namespace subdiv
