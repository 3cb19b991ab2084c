// Which bound each scheme gets, and the rates the analysis gives where the
// paper has none (docs/depth.md).

#include "subdiv/depth/depth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "depth/dual_face_bound.h"
#include "depth/nested_linear_surface.h"
#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/analysis/regular_smoothness.h"
#include "subdiv/analysis/spectrum.h"
#include "subdiv/core/error.h"
#include "subdiv/depth/depth_bound.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/refine/subdivision_matrix.h"
#include "subdiv/rules/bilinear.h"
#include "subdiv/rules/linear.h"

namespace subdiv {

namespace {

bool all_quads(const PolygonMesh& mesh) {
  for (Index f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_size(f) != 4) return false;
  return true;
}

// The faces a regular interior vertex has; a regular boundary vertex has half.
int regular_faces(const Scheme& scheme) {
  return scheme.split == SplitRule::quad || scheme.split == SplitRule::sqrt2 ? 4 : 6;
}

bool is_regular(const Scheme& scheme, const Configuration& c) {
  const int regular = regular_faces(scheme);
  return (c.kind == Configuration::Kind::interior && c.k == regular) ||
         (c.kind == Configuration::Kind::boundary && c.k == regular / 2);
}

// Rate at which vertex-to-limit distances contract near a configuration. A
// vertex's distance to its limit is a linear functional of the control
// points that vanishes on the eigenvalue-1 component (the limit itself).
// Near an extraordinary configuration the subdominant component survives,
// so the rate is |lambda_1|. At the regular configuration the subdominant
// eigenvectors are linear functions, which the regular limit functional
// also annihilates, so the rate is the next eigenvalue, |lambda_3|
// (1/4 for Loop and Catmull-Clark, as in the paper's regular bounds).
double configuration_rate(const Scheme& scheme, const Configuration& c, const RefineOptions& rules) {
  AnalysisOptions options;
  options.characteristic_map = false;
  options.masks = false;  // the rate reads the spectrum alone
  options.regular_rules = false;  // the spectrum alone
  options.rules = rules;  // the rules bounded (piecewise-smooth ones change the matrices)
  options.rules.start_level = 0;
  const ConfigurationAnalysis a = analyze(scheme, c, options);
  const std::size_t index = is_regular(scheme, c) ? 3 : 1;
  if (a.leading.size() <= index)
    throw InvalidInputError(std::string(scheme.name) + ": no depth bound: the analysis of " + c.name() +
                            " found no subdominant eigenvalue");
  // The analysis's matrix spans `period` steps (the sqrt3 split's two): the
  // rate of one step is its root.
  return std::pow(std::abs(a.leading[index]), 1.0 / scheme.traits.period);
}

// The configurations of the mesh's vertices, each with a vertex that has it
// (kInvalidIndex for the regular ones that refinement creates everywhere).
std::map<std::pair<int, int>, Index> configurations_present(const PolygonMesh& mesh, const Scheme& scheme,
                                                            BoundaryInterpolation boundary) {
  const MeshTopology t(mesh);
  const int regular = regular_faces(scheme);
  std::map<std::pair<int, int>, Index> present{{{static_cast<int>(Configuration::Kind::interior), regular}, kInvalidIndex}};
  bool has_boundary = false;
  for (Index v = 0; v < t.vertex_count(); ++v) {
    const int faces = t.vertex_face_count(v);
    if (t.vertex_kind(v) == VertexKind::interior) {
      present.try_emplace({static_cast<int>(Configuration::Kind::interior), faces}, v);
    } else if (t.vertex_kind(v) == VertexKind::boundary) {
      has_boundary = true;
      // A boundary vertex with one face is a corner under edge-and-corner
      // interpolation; edge-only moves it along the boundary curve.
      const bool corner = faces == 1 && boundary == BoundaryInterpolation::edge_and_corner;
      present.try_emplace(corner ? std::pair{static_cast<int>(Configuration::Kind::corner), 1}
                                 : std::pair{static_cast<int>(Configuration::Kind::boundary), faces},
                          v);
    }
  }
  if (has_boundary) present.try_emplace({static_cast<int>(Configuration::Kind::boundary), regular / 2}, kInvalidIndex);
  return present;
}

struct WorstRate {
  double rate = 0.0;
  std::string where;
};

// Where the bound starts: the control mesh, or its refinement `start` steps
// down, whose vertex points are numbered last (docs/refinement.md,
// "Splits"), so control vertex v is vertex (count - control count) + v.
struct StartLevel {
  const PolygonMesh& mesh;
  Index control_vertices = 0;
  int start = 0;
  const SourceLines* lines = nullptr;

  // "file:line: vertex V" for a vertex of the start level.
  std::string vertex_name(Index v) const {
    const Index control = v - (mesh.vertex_count() - control_vertices);
    if (control < 0)
      return "vertex " + std::to_string(v) + " of the mesh after " + std::to_string(start) + " step";
    return where(lines, &SourceLines::vertex_lines, static_cast<std::size_t>(control)) + "vertex " +
           std::to_string(control);
  }
};

// The slowest rate among the configurations present; `extraordinary_only`
// leaves the regular ones out. A configuration the analysis does not cover
// is refused naming a vertex that has it.
WorstRate worst_rate(const StartLevel& level, const Scheme& scheme, const DepthOptions& options,
                     bool extraordinary_only) {
  WorstRate worst;
  const BoundaryInterpolation boundary = boundary_of(level.mesh, options.refine);
  for (const auto& [configuration, vertex] : configurations_present(level.mesh, scheme, boundary)) {
    Configuration c;
    c.kind = static_cast<Configuration::Kind>(configuration.first);
    c.k = configuration.second;
    if (extraordinary_only && is_regular(scheme, c)) continue;
    double rate = 0.0;
    try {
      rate = configuration_rate(scheme, c, options.refine);
    } catch (const InvalidInputError& e) {
      if (vertex == kInvalidIndex) throw;
      throw InvalidInputError(level.vertex_name(vertex) + ": no depth bound for its configuration: " + e.what() +
                              " (limit positions and adaptive refinement need no bound)");
    }
    if (rate > worst.rate || worst.where.empty()) worst = {rate, c.name()};
  }
  return worst;
}

LimitOptions limit_options(const DepthOptions& options) {
  LimitOptions limit;
  limit.normals = false;
  limit.refine = options.refine;
  limit.refine.on_level = nullptr;
  return limit;
}

PolygonMesh refined(const PolygonMesh& mesh, const Scheme& scheme, const DepthOptions& options, int levels) {
  if (levels == 0) return mesh;
  RefineOptions steps = options.refine;
  steps.levels = levels;
  steps.on_level = nullptr;
  return refine(mesh, scheme, steps);
}

// The vertices' distances to their limits, every limit from masks: an
// approximated limit would leave the bound's amplitude unknown.
LimitDistances measured_distances(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& limit) {
  LimitDistances distances = resolved_limit_distances(mesh, scheme, limit);
  if (distances.approximated > 0)
    throw InvalidInputError(std::string(scheme.name) + ": no depth bound: the limits of " +
                            std::to_string(distances.approximated) + " of the " + std::to_string(mesh.vertex_count()) +
                            " vertices at level " + std::to_string(limit.refine.start_level) +
                            " are only approximated (no configuration's masks match them after four isolation "
                            "levels), so the bound's amplitude is unknown");
  return distances;
}

int max_valence(const PolygonMesh& mesh) {
  const MeshTopology t(mesh);
  int worst = 0;
  for (Index v = 0; v < t.vertex_count(); ++v) worst = std::max(worst, static_cast<int>(t.valence(v)));
  return worst;
}

// Doo-Sabin (docs/depth.md, "Doo-Sabin"): the paper's Theorem 5 from the level
// at which every extraordinary face (!= 4 sides) has the canonical two-ring
// neighbourhood, plus a term for those faces from powers of their local
// subdivision matrix (depth/dual_face_bound.h).
constexpr int kMaxDualStart = 6;
constexpr std::int64_t kMaxDualStartFaces = std::int64_t{1} << 22;

DepthBound dual_depth_bound(const PolygonMesh& mesh, const Scheme& scheme, const DepthOptions& options) {
  if (scheme.traits.paper_depth_bound != PaperDepthBound::doo_sabin_theorem_5)
    throw InvalidInputError(std::string(scheme.name) + ": no depth bound for this dual-split scheme (the bound is "
                            "written for Doo-Sabin's rules)");
  PolygonMesh level = refined(mesh, scheme, options, 1);
  std::map<int, DualFaceOperator> operators;
  const auto operator_at = [&](int k) -> const DualFaceOperator& {
    auto it = operators.find(k);
    if (it == operators.end()) it = operators.emplace(k, dual_face_operator(scheme, k, options.refine)).first;
    return it->second;
  };
  for (int start = 1;; ++start) {
    const MeshTopology t(level);
    std::vector<Index> extraordinary;
    for (Index f = 0; f < t.face_count(); ++f)
      if (t.face_size(f) != 4) extraordinary.push_back(f);
    if (extraordinary.empty()) {
      DepthBound bound = doo_sabin_bound(max_second_difference(level), start);
      bound.scheme = std::string(scheme.name);
      return bound;
    }
    // Faces at the boundary stay there, outside the canonical layout: their
    // operator is read off this level's step to the next, once the next
    // level's neighbourhood repeats this one's.
    RefineOptions one = options.refine;
    one.levels = 1;
    one.on_level = nullptr;
    const auto on_boundary = [&](Index f) {
      const auto face = t.face_vertices(f);
      return std::any_of(face.begin(), face.end(), [&](Index v) { return t.vertex_kind(v) != VertexKind::interior; });
    };
    std::optional<StencilTable> step;
    std::optional<MeshTopology> child_topology;
    PolygonMesh child;
    if (std::any_of(extraordinary.begin(), extraordinary.end(), on_boundary)) {
      step = std::move(refine_stencils(level, scheme, one, &child).front());  // the child too, in one pass
      child_topology.emplace(child);
    }
    std::vector<const DualFaceOperator*> face_operators;
    std::vector<Eigen::MatrixXd> neighbourhoods;
    std::vector<DualFaceOperator> boundary_operators;
    boundary_operators.reserve(extraordinary.size());
    bool ready = true;
    for (const Index f : extraordinary) {
      if (on_boundary(f)) {
        std::optional<DualFaceOperator> op =
            local_face_operator(t, *step, *child_topology, f, boundary_vertex_limit(scheme));
        if (!op) {
          ready = false;
          break;
        }
        boundary_operators.push_back(std::move(*op));
        face_operators.push_back(&boundary_operators.back());
        neighbourhoods.push_back(local_neighbourhood(t, level.positions, f));
        continue;
      }
      const DualFaceOperator& op = operator_at(t.face_size(f));
      std::optional<Eigen::MatrixXd> around = canonical_neighbourhood(op, t, level.positions, f);
      if (!around) {
        ready = false;
        break;
      }
      face_operators.push_back(&op);
      neighbourhoods.push_back(std::move(*around));
    }
    if (!ready) {
      if (start == kMaxDualStart || 4 * level.corner_count() > kMaxDualStartFaces)
        throw InvalidInputError(std::string(scheme.name) + ": no depth bound: after " + std::to_string(start) +
                                " steps the faces with other than 4 sides are still too close to each other or to "
                                "the boundary for the bound");
      level = step ? std::move(child) : refine(level, scheme, one);
      continue;
    }
    double amplitude = 0.0, rate = 0.0;
    int worst = 0;
    for (std::size_t i = 0; i < extraordinary.size(); ++i) {
      const DualFaceOperator& op = *face_operators[i];
      const double a = dual_face_amplitude(op, neighbourhoods[i]);
      if (a > amplitude || worst == 0) {
        amplitude = a;
        worst = op.k;
      }
      rate = std::max(rate, op.rate);
    }
    const double second_difference = max_second_difference(level);
    DepthBound bound = doo_sabin_bound(second_difference, start);
    bound.scheme = std::string(scheme.name);
    bound.source = "paper (regular) + local subdivision matrix (extraordinary)";
    // Near the faces the regular term's second differences are bounded by
    // the faces' own term, so the two together hold everywhere from `start`
    // on (docs/depth.md, "Doo-Sabin").
    bound.terms.push_back({"largest distance or second difference / 4 that the local subdivision matrix gives any "
                           "later step near the extraordinary faces after " + std::to_string(start) +
                               " steps, over |lambda_1|^steps (worst at a face of " + std::to_string(worst) +
                               " sides), contracted by |lambda_1|",
                           amplitude, rate});
    return bound;
  }
}

// Steps after which the split's child faces nest in the parent's: one for
// the quad and triangle splits, two for the sqrt3 and sqrt2 splits (their
// second child level is the parent's faces split 1-to-9 or 1-to-4).
int nesting_steps(const Scheme& scheme) {
  return scheme.split == SplitRule::sqrt3 || scheme.split == SplitRule::sqrt2 ? 2 : 1;
}

// The largest distance between `level`'s linear surface (flat triangles,
// bilinear quads) and the scheme's vertices `samples` nesting periods down,
// at the same parameter: the linear or bilinear scheme's refinement of
// `level` numbers its vertices as the scheme's own (the same split); the
// rotating splits place them by their parameters over two steps
// (depth/nested_linear_surface.h).
double linear_surface_distance(const PolygonMesh& level, int level_number, const Scheme& scheme,
                               const RefineOptions& rules, int samples) {
  const int period = nesting_steps(scheme);
  RefineOptions steps = rules;
  steps.levels = samples * period;
  steps.start_level = level_number;
  steps.on_level = nullptr;
  const PolygonMesh exact = refine(level, scheme, steps);
  PolygonMesh linear;
  if (period == 1) {
    linear = refine(level, scheme.split == SplitRule::quad ? bilinear_scheme() : linear_scheme(), steps);
  } else {
    linear = level;
    for (int i = 0; i < samples; ++i)
      linear = detail::nested_linear_refinement(linear, level_number + period * i, scheme.split);
    if (linear.face_offsets != exact.face_offsets || linear.face_indices != exact.face_indices)
      throw std::logic_error(std::string(scheme.name) + ": the nested linear surface's faces differ from the "
                             "scheme's refinement");
  }
  double worst = 0.0;
  for (std::size_t v = 0; v < exact.positions.size(); ++v)
    worst = std::max(worst, norm(exact.positions[v] - linear.positions[v]));
  return worst;
}

// Interpolating schemes with wide masks (docs/depth.md, "Interpolating
// schemes"): the level's linear surface against the limit. A nesting
// period (one step, or two of the sqrt3 and sqrt2 splits) moves the linear
// surface by at most its largest displacement D_j (new vertex against the
// period's first level's linear surface there; the difference of two nested
// linear surfaces is linear on each finer face, zero at the old vertices),
// so the distance after k periods is at most the sum of D_j, j >= k.
// D_j contracts by the slowest of |lambda_1| at the extraordinary
// configurations present and the regular rules' bound on their second
// differences' contraction; its amplitude is measured over the first two
// periods (the first period's new vertices may move further than the
// control mesh's shape gives). The bound counts periods
// (DepthBound::steps_per_level).
DepthBound interpolating_depth_bound(const PolygonMesh& mesh, const Scheme& scheme, const DepthOptions& options,
                                     const SourceLines* lines) {
  const std::string name(scheme.name);
  const int level0 = options.refine.start_level;
  const int period = nesting_steps(scheme);
  const StartLevel start{mesh, mesh.vertex_count(), 0, lines};
  const WorstRate extraordinary = worst_rate(start, scheme, options, true);  // rates per step
  bool has_boundary = false;
  {
    const MeshTopology t(mesh);
    for (Index v = 0; v < t.vertex_count() && !has_boundary; ++v) has_boundary = t.vertex_kind(v) != VertexKind::interior;
  }
  // The interior rule's bound is per step, the boundary rule's per period of
  // the scheme (regular_boundary_rule()): both are taken per step here.
  RegularSmoothness regular = regular_smoothness_of(scheme, options.refine, false);
  double regular_rate = regular.upper;
  std::string regular_where = "the regular interior rules";
  if (has_boundary) {
    RegularSmoothness edge;
    try {
      edge = regular_smoothness(regular_boundary_rule(scheme, options.refine));
    } catch (const InvalidInputError& e) {
      throw InvalidInputError(name + ": no depth bound on a mesh with a boundary: the contraction of the regular "
                              "boundary rules' second differences is not known (" + e.what() + ")");
    }
    const double edge_rate = std::pow(edge.upper, 1.0 / scheme.traits.period);
    if (!(edge.upper > 0.0)) {
      regular = edge;
      regular_rate = edge.upper;
    } else if (edge_rate > regular_rate) {
      regular = edge;
      regular_rate = edge_rate;
      regular_where = "the regular boundary rules";
    }
  }
  if (!(regular_rate > 0.0 && regular_rate < 1.0))
    throw InvalidInputError(name + ": no depth bound: the regular rules give no contraction of their second "
                            "differences (" + regular.reason + ")");
  double rate = regular_rate;
  std::string slowest = regular_where + "' second differences (joint spectral radius <= " +
                        std::to_string(regular_rate) + " a step)";
  if (extraordinary.rate > rate) {
    rate = extraordinary.rate;
    slowest = "|lambda_1| at " + extraordinary.where + " (analysis)";
  }
  rate = std::pow(rate, period);  // per nesting period
  RefineOptions one = options.refine;
  one.levels = period;
  one.on_level = nullptr;
  const double d0 = linear_surface_distance(mesh, level0, scheme, options.refine, 1);
  const double d1 = linear_surface_distance(refine(mesh, scheme, one), level0 + period, scheme, options.refine, 1);
  const double amplitude = std::max(d0, rate > 0.0 ? d1 / rate : 0.0) / (1.0 - rate);
  const std::string steps = period == 1 ? "step" : "period of " + std::to_string(period) + " steps";
  DepthBound bound{name,
                   "analysis (interpolating)",
                   0,
                   {{"largest displacement of the new vertices of a " + steps +
                         " from the level's linear surface (the larger of the first two), summed over the " +
                         (period == 1 ? std::string("steps") : "periods of " + std::to_string(period) + " steps") +
                         " to come, contracted by the slowest rate: " + slowest,
                     amplitude, rate}}};
  bound.measure = DepthMeasure::surface_to_limit;
  bound.steps_per_level = period;
  return bound;
}

}  // namespace

// An interpolating scheme whose rules reach beyond the one-ring (the
// Butterfly schemes, Kobbelt's): the limit mask at the regular configuration is the
// centre alone, yet new vertices leave the control mesh's faces (unlike the
// linear schemes, whose control mesh is its own limit).
// Only the regular configuration's invariant matrix and its limit mask are
// read (not the full analysis: its spectrum and the regular rules'
// smoothness take seconds for the wide rotating schemes).
bool interpolates_with_wide_masks(const Scheme& scheme, const DepthOptions& options) {
  const AnalysisOptions defaults;
  const LocalSubdivisionMatrix m = invariant_subdivision_matrix(
      scheme, {Configuration::Kind::interior, regular_faces(scheme), CornerType::convex}, defaults.max_rings,
      options.refine);
  if (!m.invariant || m.rings <= 1) return false;
  const std::optional<Eigen::VectorXd> limit = left_eigenvector(m.S, 1.0, defaults.tolerance);
  if (!limit) return false;
  const Eigen::VectorXd& mask = *limit;
  return std::abs(mask[0] - 1.0) < 1e-9 && mask.tail(mask.size() - 1).cwiseAbs().maxCoeff() < 1e-9;
}

std::optional<std::string> depth_bound_unavailable(const Scheme& scheme, const DepthOptions& options) {
  if (scheme.fast_path.two_steps) return depth_bound_unavailable(*scheme.fast_path.two_steps, options);
  if (const auto reason = limit_unavailable(scheme)) return "no depth bound without limit positions, and " + *reason;
  if (scheme.split == SplitRule::dual && scheme.steps)
    return "no depth bound for composite schemes that end with a dual step (gcc and midpoint of even degree) yet: "
           "the dual bound is written for Doo-Sabin's rules, and a single vertex-to-limit term does not bound a "
           "dual scheme (its first levels mix the subdominant component with faster ones)";
  if (scheme.split == SplitRule::dual) return std::nullopt;
  if (!is_primal(scheme.split) && scheme.split != SplitRule::sqrt3 && scheme.split != SplitRule::sqrt2)
    return std::string("no depth bound for the ") + to_string(scheme.split) +
           " yet: the bounds are written for the quad, triangle, sqrt3, sqrt2 and dual splits";
  return std::nullopt;
}

DepthBound depth_bound(const PolygonMesh& mesh, const Scheme& scheme, const DepthOptions& options,
                       const SourceLines* lines) {
  // Two steps of 4-8 are a quad-split scheme's level (Scheme::two_steps):
  // the bound is that scheme's, counted in levels of two steps.
  if (scheme.fast_path.two_steps) {
    DepthBound bound = depth_bound(mesh, *scheme.fast_path.two_steps, options, lines);
    bound.scheme = std::string(scheme.name);
    bound.steps_per_level = 2;
    return bound;
  }
  if (const auto reason = depth_bound_unavailable(scheme, options))
    throw InvalidInputError(std::string(scheme.name) + ": " + *reason);
  if (scheme.split == SplitRule::dual) return dual_depth_bound(mesh, scheme, options);
  if (interpolates_with_wide_masks(scheme, options)) return interpolating_depth_bound(mesh, scheme, options, lines);
  // Quad-split schemes on a mesh with other faces: the bound starts after
  // the first step, which makes every face a quad (as the paper does for
  // Doo-Sabin and the survey for Catmull-Clark).
  const int start = scheme.split == SplitRule::quad && !all_quads(mesh) ? 1 : 0;
  const PolygonMesh first = refined(mesh, scheme, options, start);
  LimitOptions limit = limit_options(options);
  limit.refine.start_level += start;
  const LimitDistances distances = measured_distances(first, scheme, limit);
  const StartLevel level{first, mesh.vertex_count(), start, lines};

  // The paper's bounds cover regular vertices (Catmull-Clark) or only the
  // vertices that already exist (Loop: the proof of Theorem 3 follows a
  // vertex point, never a new edge point). Near an extraordinary vertex the
  // distances of the new vertices decay like |lambda_1| there, slower than
  // the paper's rate: measured, the paper's Loop bound fails on meshes with
  // valence 8 or 32 (docs/depth.md, "Extraordinary vertices"). That term is added.
  const PaperDepthBound paper = scheme.traits.paper_depth_bound;
  if (paper == PaperDepthBound::loop_theorem_3 || paper == PaperDepthBound::cheng_catmull_clark) {
    DepthBound bound = paper == PaperDepthBound::loop_theorem_3
                           ? loop_paper_bound(scheme, distances.max, max_valence(first))
                           : cheng_catmull_clark_bound(max_second_difference(first), start);
    bound.scheme = std::string(scheme.name);
    const WorstRate extraordinary = worst_rate(level, scheme, options, true);
    if (!extraordinary.where.empty()) {
      bound.source = "paper (regular) + analysis (extraordinary)";
      bound.terms.push_back({"largest control-vertex-to-limit distance, contracted by |lambda_1| at " +
                                 extraordinary.where + " (analysis)",
                             distances.max, extraordinary.rate});
    }
    return bound;
  }

  const WorstRate worst = worst_rate(level, scheme, options, false);
  DepthBound bound{std::string(scheme.name),
                   "analysis",
                   start,
                   {{"largest control-vertex-to-limit distance, contracted by the slowest rate, at " + worst.where +
                         " (analysis)",
                     distances.max, worst.rate}}};
  // A rotating split (sqrt3: period 2) contracts by the analysis's rate over
  // a whole period, not step by step: the new points of the period's first
  // steps may lie further from their limits than the old vertices did. Each
  // such level's own largest distance starts a term of its own, contracted
  // per period from there.
  PolygonMesh later = first;
  for (int j = 1; j < scheme.traits.period; ++j) {
    RefineOptions step = limit.refine;
    step.levels = 1;
    step.on_level = nullptr;
    later = refine(later, scheme, step);
    limit.refine.start_level += 1;
    const double at_j = measured_distances(later, scheme, limit).max;
    bound.terms.push_back({"largest vertex-to-limit distance after " + std::to_string(j) + " of a period of " +
                               std::to_string(scheme.traits.period) + " steps, contracted by the same rate from there",
                           worst.rate > 0.0 ? at_j / std::pow(worst.rate, j)
                                            : std::numeric_limits<double>::infinity(),
                           worst.rate});
  }
  return bound;
}

std::vector<LevelCost> level_costs(const PolygonMesh& mesh, const Scheme& scheme, int levels) {
  if (scheme.fast_path.two_steps) return level_costs(mesh, *scheme.fast_path.two_steps, levels);  // levels of two steps, as its bound
  const MeshTopology t(mesh);
  LevelCost cost{0, mesh.vertex_count(), mesh.face_count(), t.edge_count(), mesh.corner_count(), 0};
  // Dual split: boundary and V-face counts of the current level.
  std::int64_t boundary_edges = 0, boundary_vertices = 0, v_faces = 0, v_face_corners = 0;
  if (scheme.split == SplitRule::dual) {
    for (Index e = 0; e < t.edge_count(); ++e) boundary_edges += t.is_boundary_edge(e) ? 1 : 0;
    for (Index v = 0; v < t.vertex_count(); ++v) {
      const bool boundary = t.vertex_kind(v) == VertexKind::boundary;
      boundary_vertices += boundary ? 1 : 0;
      if (dual_split_has_v_face(t, v)) {
        ++v_faces;
        v_face_corners += t.vertex_face_count(v) + (boundary ? 2 : 0);
      }
    }
  }
  // Sqrt3 split: the boundary edges of the current level.
  std::int64_t sqrt3_boundary_edges = 0;
  if (scheme.split == SplitRule::sqrt3)
    for (Index e = 0; e < t.edge_count(); ++e) sqrt3_boundary_edges += t.is_boundary_edge(e) ? 1 : 0;
  std::vector<LevelCost> out;
  for (int level = 0; level <= levels; ++level) {
    cost.level = level;
    cost.bytes = 24 * cost.vertices + 4 * (cost.corners + cost.faces + 1);
    out.push_back(cost);
    LevelCost next = cost;
    switch (scheme.split) {
      case SplitRule::quad:
        // A face of c corners becomes c quads around its face point; an edge
        // becomes two plus one per face side (face point to edge point).
        next.vertices = cost.vertices + cost.edges + cost.faces;
        next.faces = cost.corners;
        next.edges = 2 * cost.edges + cost.corners;
        next.corners = 4 * cost.corners;
        break;
      case SplitRule::dual: {
        // A child vertex per corner and two per boundary edge; a child face
        // per face (its corners), per edge (4 corners) and per vertex with one
        // (its faces' corners, 2 more on a boundary: src/topology/dual_split.cpp).
        // The child's boundary: two edges per boundary edge and per boundary
        // vertex; from level 1 every vertex has a V-face.
        next.vertices = cost.corners + 2 * boundary_edges;
        next.faces = cost.faces + cost.edges + v_faces;
        next.corners = cost.corners + 4 * cost.edges + v_face_corners;
        next.edges = (next.corners + boundary_edges + boundary_vertices) / 2;
        const std::int64_t child_boundary_edges = boundary_edges + boundary_vertices;
        boundary_vertices = 2 * boundary_edges;
        boundary_edges = child_boundary_edges;
        v_faces = next.vertices;
        v_face_corners = next.corners + 2 * boundary_vertices;
        break;
      }
      case SplitRule::sqrt3: {
        // Two triangles per interior edge, one per boundary edge; a face point
        // per face, and on trisecting steps two boundary points per boundary
        // edge (whose faces then have no face point: counted anyway), which
        // triple the boundary edges (counted on every step): exact on closed
        // meshes, at most this with a boundary.
        next.vertices = cost.vertices + cost.faces + 2 * sqrt3_boundary_edges;
        next.faces = 2 * cost.edges - sqrt3_boundary_edges;
        next.corners = 3 * next.faces;
        sqrt3_boundary_edges *= 3;
        next.edges = (next.corners + sqrt3_boundary_edges) / 2;
        break;
      }
      case SplitRule::sqrt2:
        // A quad per edge around its face points and ends; an edge per corner.
        next.vertices = cost.vertices + cost.faces;
        next.faces = cost.edges;
        next.corners = 4 * cost.edges;
        next.edges = cost.corners;
        break;
      case SplitRule::midedge:
        // A vertex per edge; a face per face and per vertex (closed meshes);
        // an edge per corner, joining the points of the corner's two edges.
        next.vertices = cost.edges;
        next.faces = cost.faces + cost.vertices;
        next.corners = 2 * cost.corners;
        next.edges = cost.corners;
        break;
      case SplitRule::identity:
        break;
      case SplitRule::quasi_4_8:
        // Geometric: at most every edge split and every triangle bisected
        // (Algorithm 1 splits at most one edge per face): an upper bound.
        next.vertices = cost.vertices + cost.edges;
        next.faces = 2 * cost.faces;
        next.corners = 3 * next.faces;
        next.edges = cost.edges + cost.edges + cost.faces;
        break;
      case SplitRule::triangle:
        // A triangle becomes four; an edge two, plus three inside each face.
        next.vertices = cost.vertices + cost.edges;
        next.faces = 4 * cost.faces;
        next.edges = 2 * cost.edges + 3 * cost.faces;
        next.corners = 12 * cost.faces;
        break;
    }
    cost = next;
  }
  return out;
}

DepthCheck check_depth(const PolygonMesh& mesh, const Scheme& scheme, const DepthBound& bound, int depth,
                       const DepthOptions& options) {
  DepthCheck check;
  check.depth = depth;
  check.bound = bound.at(depth);
  const int steps = bound.steps_per_level;  // refined and measured with the scheme's own steps and limits
  // Measured at the level's own number (the sqrt3 split's boundary steps
  // alternate): every vertex against its limit, or the level's linear
  // surface against the next level's vertices, which are on the limit.
  const auto measure = [&](const PolygonMesh& level, int number) {
    if (bound.measure == DepthMeasure::surface_to_limit)
      return std::pair{linear_surface_distance(level, number, scheme, options.refine, 1), Index{0}};
    LimitOptions limit = limit_options(options);
    limit.refine.start_level = number;
    const LimitDistances distances = resolved_limit_distances(level, scheme, limit);
    return std::pair{distances.max, distances.approximated};
  };
  if (depth > 0) {
    // One hierarchy, its last level kept: depth - 1, then one more level of
    // the same refinement (the level's state carried, not restarted).
    RefineOptions run = options.refine;
    run.levels = steps * (depth - 1);
    run.on_level = nullptr;
    Hierarchy levels = refine_hierarchy(mesh, scheme, run, KeepLevels::last);
    check.has_previous = true;
    check.measured_previous = measure(levels.finest().mesh, levels.finest().level).first;
    refine_further(levels, scheme, steps, run, KeepLevels::last);
    std::tie(check.measured, check.approximated) = measure(levels.finest().mesh, levels.finest().level);
  } else {
    std::tie(check.measured, check.approximated) = measure(mesh, options.refine.start_level);
  }
  return check;
}

}  // namespace subdiv
