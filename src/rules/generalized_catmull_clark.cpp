// Generalized Catmull-Clark and midpoint schemes: all of their weights.
//
// Source: Q. Chen, H. Prautzsch, "Generalized Catmull-Clark subdivision",
// Karlsruhe Reports in Informatics 2012,16, sections 1 and 2.
//   R (Figure 1.1, top): every face splits into quads around its centre
//     (the centroid), every edge gets its midpoint, old vertices stay: the
//     bilinear scheme's masks on the quad split.
//   B_{alpha,beta} (Figure 1.3): an interior vertex v of valence m becomes
//       alpha v + beta/m sum e_i + gamma/m sum d_i,   gamma = 1 - alpha - beta,
//     e_i its edge neighbours, d_i the vertex opposite v in each of its quads.
//     The figure is lost in the text; this form is the one the paper's
//     Catmull-Clark decomposition fixes: after R, e_i = (v + v_i)/2 and d_i
//     = the centroid of face i, so B R puts alpha + beta/2 + gamma/4 on v,
//     (beta/2 + gamma/2)/m on each v_i and gamma/(4m) on each opposite
//     vertex: the paper's alpha~, beta~/m, gamma~/m (Figure 1.2), and B = A^2
//     for alpha = 1/4, beta = 1/2 (tests/rules/generalized_catmull_clark_test.cpp).
//     Boundary vertices are not interior and stay where they are.
//   A (Figure 1.1, bottom): the dual mesh of the face centres. In M_n-bar it
//     always follows B_r ... B_1 R, whose mesh has the topology of R's quad
//     split of the level's parent P; its face centres are one per corner of
//     P and its faces one per face, edge and vertex of P: the dual split of
//     P (topology/dual_split.cpp). So A is a dual split of P whose corner
//     point is the centroid of the quad split's child quad of that corner
//     (its four vertices as the quad split numbers them). At a boundary the
//     dual split adds the midpoints of the boundary edges of the quad mesh
//     (Doo's construction): the boundary point of P's boundary edge (a, b)
//     near a is (a + (a + b)/2) / 2 = 3/4 a + 1/4 b, since B keeps boundary
//     vertices and R puts the edge midpoint.
// Boundaries: odd degrees keep the boundary polygon (R adds its midpoints,
// B does not move boundary vertices): the limit surface interpolates the
// control mesh's boundary polygon, a piecewise linear curve. Even degrees
// cut it by Chaikin's rule each level (A's boundary points): the boundary
// limit is the quadratic B-spline of the boundary polygon, as Doo-Sabin's.
// Creases, corner tags and holes have no rule (refused by refine.cpp).

#include "subdiv/rules/generalized_catmull_clark.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "subdiv/core/error.h"
#include "subdiv/rules/bilinear.h"

namespace subdiv {

std::pair<double, double> SmoothingWeights::at(int m) const noexcept {
  for (const AtValence& v : valences)
    if (v.valence == m) return {v.alpha, v.beta};
  if (rule == Rule::catmull_clark) return {1.0 - 3.0 / m, 2.0 / m};
  return {alpha, beta};
}

namespace {

// B_{alpha,beta} at vertex v of a quad mesh; the step's one SmoothingWeights
// is parameters.smoothing.front() (generalized_catmull_clark_steps).
void smoothing_point(const LevelView& level, Index v, VertexRule rule, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  if (rule != VertexRule::smooth || t.vertex_kind(v) != VertexKind::interior) return mask.add(v, 1.0);
  const int m = t.valence(v);
  const auto [alpha, beta] = std::get<DegreeParameters>(level.parameters).smoothing.front().at(m);
  const double gamma = 1.0 - alpha - beta;
  mask.add(v, alpha);
  for (const Index e : t.vertex_edges(v)) mask.add(t.other_vertex(e, v), beta / m);
  for (const Index c : t.vertex_corners(v)) {
    if (t.face_size(t.corner_face(c)) != 4)
      throw TopologyError("the smoothing operator B needs a quad mesh, but face " +
                          std::to_string(t.corner_face(c)) + " has " + std::to_string(t.face_size(t.corner_face(c))) +
                          " vertices");
    mask.add(t.corner_vertex(t.corner_next(t.corner_next(c))), gamma / m);
  }
}

// The quad split's numbering of the level parent P's children (quad_split.cpp):
// [face points | edge points | vertex points].
Index quad_face_point(const MeshTopology&, Index f) { return f; }
Index quad_edge_point(const MeshTopology& t, Index e) { return t.face_count() + e; }
Index quad_vertex_point(const MeshTopology& t, Index v) { return t.face_count() + t.edge_count() + v; }

// A: the centre of the quad split's child quad of corner c of P, i.e. of
// [vertex point, point of the edge leaving c, face point, point of the edge
// entering c].
void averaging_corner(const LevelView& level, Index c, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  mask.add(quad_vertex_point(t, t.corner_vertex(c)), 0.25);
  mask.add(quad_edge_point(t, t.corner_edge(c)), 0.25);
  mask.add(quad_face_point(t, t.corner_face(c)), 0.25);
  mask.add(quad_edge_point(t, t.corner_edge(t.corner_prev(c))), 0.25);
}

// A at a boundary: the midpoint of the quad mesh's boundary edge from the
// vertex point of `vertex` to the point of `edge`.
void averaging_boundary(const LevelView& level, Index edge, Index vertex, MaskBuilder& mask) {
  mask.add(quad_vertex_point(level.topology, vertex), 0.5);
  mask.add(quad_edge_point(level.topology, edge), 0.5);
}

const Scheme& smoothing_step() {
  static const Scheme scheme = [] {
    return Scheme{.name = "smoothing B",
                  .summary = "B_{alpha,beta}: each interior vertex of a quad mesh an affine combination of its 1-ring",
                  .citation = "Q. Chen, H. Prautzsch: Generalized Catmull-Clark subdivision, 2012, Figure 1.3",
                  .split = SplitRule::identity,
                  .masks = {.vertex_point = smoothing_point},
                  .parameters = DegreeParameters{}};
  }();
  return scheme;
}

const Scheme& averaging_step() {
  static const Scheme scheme = [] {
    return Scheme{.name = "averaging A",
                  .summary = "A after R: the dual mesh of the quad mesh's face centres",
                  .citation = "Q. Chen, H. Prautzsch: Generalized Catmull-Clark subdivision, 2012, Figure 1.1",
                  .split = SplitRule::dual,
                  .masks = {.corner_point = averaging_corner, .boundary_point = averaging_boundary}};
  }();
  return scheme;
}

void check_weights(double alpha, double beta, int step, const std::string& where) {
  if (!(std::isfinite(alpha) && std::isfinite(beta) && alpha >= 0.0 && beta >= 0.0 && alpha + beta > 0.0 &&
        alpha + beta < 1.0))
    throw ParameterError(fmt::format("B_{}{}: alpha = {}, beta = {} lie outside the paper's range (alpha, beta >= "
                                        "0, 0 < alpha + beta < 1)",
                                        step, where, alpha, beta));
}

void check_smoothing(const SmoothingWeights& w, int step) {
  if (w.rule == SmoothingWeights::Rule::constant) check_weights(w.alpha, w.beta, step, "");
  for (const SmoothingWeights::AtValence& v : w.valences) {
    if (v.valence < 3)
      throw ParameterError(fmt::format("B_{}: valence {} has no weights (interior valences are >= 3)", step, v.valence));
    check_weights(v.alpha, v.beta, step, fmt::format(" at valence {}", v.valence));
  }
}

// A level of degree n reads n / 2 + 1 face rings around a vertex (R, then
// r smoothing steps of one ring each, then A).
int analysis_rings_of_degree(int n) { return n / 2 + 1; }

std::vector<Scheme> steps_of(const SchemeParameters& parameters) { return generalized_catmull_clark_steps(parameters); }

// The family's parameter check: the degree, the count of smoothing
// operators and each operator's weights.
void check_degree(std::string_view, const SchemeParameters& parameters) { generalized_catmull_clark_steps(parameters); }

// Midpoint subdivision's smoothing is A^2 (alpha = 1/4, beta = 1/2) at every
// valence; other weights make another member of the generalized family.
void check_midpoint(std::string_view name, const SchemeParameters& parameters) {
  check_degree(name, parameters);
  for (const SmoothingWeights& w : std::get<DegreeParameters>(parameters).smoothing)
    if (w.rule != SmoothingWeights::Rule::constant || w.alpha != 0.25 || w.beta != 0.5 || !w.valences.empty())
      throw ParameterError(std::string(name) + " has alpha = 1/4, beta = 1/2 (midpoint subdivision): give other "
                           "weights to " + std::string(generalized_catmull_clark_scheme().name));
}

// On a regular grid a level of odd degree n = 2r + 1 is R, the bilinear
// split, then r smoothing steps. Where every step's weights at valence 4
// are alpha = 1/4, beta = 1/2 (midpoint's, and Catmull-Clark's at m = 4),
// B there is the tensor product of (1/4, 1/2, 1/4), so the level is that of
// the uniform B-spline of degree n along each grid line: the mask
// (1/2, 1, 1/2) of R convolved r times with (1/4, 1/2, 1/4), whose even and
// odd taps are RegularGrid's weights while they fit it (n = 3, 5, 7).
std::optional<RegularGrid> regular_grid(const SchemeParameters& parameters) {
  const DegreeParameters* degree = degree_parameters(parameters);
  if (!degree || degree->degree % 2 == 0 || degree->degree > 7) return std::nullopt;
  for (const SmoothingWeights& w : degree->smoothing)
    if (w.at(4) != std::pair{0.25, 0.5}) return std::nullopt;
  std::vector<double> mask{0.5, 1.0, 0.5};  // centred: mask[h + k] at fine offset k
  for (int step = 0; step < (degree->degree - 1) / 2; ++step) {
    std::vector<double> wider(mask.size() + 2, 0.0);
    for (std::size_t k = 0; k < mask.size(); ++k)
      for (std::size_t q = 0; q < 3; ++q) wider[k + q] += mask[k] * (q == 1 ? 0.5 : 0.25);
    mask.swap(wider);
  }
  const int h = static_cast<int>(mask.size() / 2);
  auto tap = [&](int offset) { return std::abs(offset) <= h ? mask[static_cast<std::size_t>(h + offset)] : 0.0; };
  RegularGrid rule{};
  for (int d = -2; d <= 2; ++d) rule.even[static_cast<std::size_t>(d + 2)] = tap(-2 * d);  // coarse i + d of fine 2i
  for (int d = -1; d <= 2; ++d) rule.odd[static_cast<std::size_t>(d + 1)] = tap(1 - 2 * d);  // of fine 2i + 1
  return rule;
}

Scheme composite(std::string_view name, std::string_view summary, std::string_view citation, SmoothingWeights weights,
                 ParameterCheck check) {
  return Scheme{.name = name,
                .summary = summary,
                .citation = citation,
                .split = SplitRule::quad,
                .traits = {.analysis_rings = analysis_rings_of_degree(3)},
                .steps = steps_of,
                .fast_path = {.regular_grid_of = regular_grid},
                .parameters = DegreeParameters{.degree = 3, .smoothing = {std::move(weights)}},
                .parameter_check = check};
}

}  // namespace

std::vector<Scheme> generalized_catmull_clark_steps(const SchemeParameters& parameters) {
  const DegreeParameters* degree = degree_parameters(parameters);
  if (!degree) throw ParameterError("generalized Catmull-Clark: the parameters hold no degree");
  const int n = degree->degree;
  if (n < 2) throw ParameterError("generalized Catmull-Clark: the degree must be >= 2, not " + std::to_string(n));
  const int r = (n - 1) / 2;
  const auto given = static_cast<int>(degree->smoothing.size());
  if (r > 0 && given != 1 && given != r)
    throw ParameterError(fmt::format("degree {} has {} smoothing operators B_1 .. B_{}, but {} sets of weights are "
                                        "given (give 1 for all of them, or {})",
                                        n, r, r, given, r));
  std::vector<Scheme> steps{bilinear_scheme()};  // R
  for (int i = 0; i < r; ++i) {
    const SmoothingWeights& w = degree->smoothing[static_cast<std::size_t>(given == 1 ? 0 : i)];
    check_smoothing(w, i + 1);
    Scheme b = smoothing_step();
    std::get<DegreeParameters>(b.parameters).smoothing = {w};
    steps.push_back(std::move(b));
  }
  if (n % 2 == 0) steps.push_back(averaging_step());
  return steps;
}

void set_degree(Scheme& scheme, int degree) {
  DegreeParameters* parameters = degree_parameters(scheme.parameters);
  if (!parameters || !scheme.steps) throw ParameterError(std::string(scheme.name) + " has no degree");
  if (degree < 2) throw ParameterError(std::string(scheme.name) + ": the degree must be >= 2, not " + std::to_string(degree));
  parameters->degree = degree;
  scheme.traits.analysis_rings = analysis_rings_of_degree(degree);
  scheme.split = degree % 2 == 1 ? SplitRule::quad : SplitRule::dual;
}

std::string describe_smoothing(const SchemeParameters& parameters) {
  const DegreeParameters& p = std::get<DegreeParameters>(parameters);
  std::string out = "n=" + std::to_string(p.degree);
  const int r = (p.degree - 1) / 2;
  const bool shared = p.smoothing.size() == 1;
  for (int i = 0; i < (shared ? std::min(r, 1) : r) && i < static_cast<int>(p.smoothing.size()); ++i) {
    const SmoothingWeights& w = p.smoothing[static_cast<std::size_t>(i)];
    const std::string which = shared && r > 1 ? fmt::format("B_1..B_{}", r) : fmt::format("B_{}", i + 1);
    out += fmt::format("{} {}: ", i == 0 ? "," : ";", which);
    out += w.rule == SmoothingWeights::Rule::catmull_clark ? std::string("alpha=1-3/m beta=2/m")
                                                           : fmt::format("alpha={:.6g} beta={:.6g}", w.alpha, w.beta);
    for (const SmoothingWeights::AtValence& v : w.valences)
      out += fmt::format(", m={}: alpha={:.6g} beta={:.6g}", v.valence, v.alpha, v.beta);
  }
  return out;
}

const Scheme& generalized_catmull_clark_scheme() {
  static const Scheme scheme = [] {
    SmoothingWeights cc;
    cc.rule = SmoothingWeights::Rule::catmull_clark;
    return composite("gcc",
                     "approximating, generalized Catmull-Clark of any degree n with smoothing weights alpha, beta (quad split "
                     "for odd n, dual for even n); default n = 3 with Catmull-Clark's weights",
                     "Q. Chen, H. Prautzsch: Generalized Catmull-Clark subdivision, Karlsruhe Reports in Informatics "
                     "2012,16",
                     cc, check_degree);
  }();
  return scheme;
}

const Scheme& midpoint_scheme() {
  static const Scheme scheme =
      composite("midpoint", "approximating, midpoint subdivision M_n of any degree n, default 3 (quad split "
                            "for odd n, dual for even n); B-splines of degree n on regular quads",
                "H. Prautzsch, Q. Chen: Analyzing midpoint subdivision, CAGD 28(7), 2011; as A^(n-1) R of Chen, "
                "Prautzsch 2012",
                SmoothingWeights{}, check_midpoint);
  return scheme;
}

}  // namespace subdiv
