#include "subdiv/analysis/limit.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/dual_limit.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"

#include "closed_form_limit.h"

namespace subdiv {

namespace {

// The masks of one configuration, from the analysis.
struct Masks {
  std::optional<Eigen::VectorXd> limit;
  std::optional<std::array<Eigen::VectorXd, 2>> tangents;
};

class MaskCache {
 public:
  MaskCache(const Scheme& scheme, const RefineOptions& rules) : scheme_(scheme), rules_(rules) {}

  const Masks& at(Configuration::Kind kind, int k) {
    const auto key = std::pair{static_cast<int>(kind), k};
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    AnalysisOptions options;
    options.characteristic_map = false;
    options.rules = rules_;
    const ConfigurationAnalysis a = analyze(scheme_, {kind, k, CornerType::convex}, options);
    if (a.matrix.invariant && a.matrix.rings != 1)
      throw InvalidInputError(std::string(scheme_.name) + ": limit masks over more than the one-ring are not supported yet");
    return cache_.emplace(key, Masks{a.limit_mask, a.tangent_masks}).first->second;
  }

 private:
  const Scheme& scheme_;
  RefineOptions rules_;
  std::map<std::pair<int, int>, Masks> cache_;
};

// The centre and its one-ring in the order of the configuration's layout:
// counter-clockwise from the first face's outgoing edge; for quads the
// edge neighbour and then the face's opposite vertex of each face; on a
// boundary, the last face's incoming neighbour closes the list.
std::vector<Index> canonical_ring(const MeshTopology& t, Index v, bool quads, bool boundary) {
  std::vector<Index> ring{v};
  const auto corners = t.vertex_corners(v);
  for (const Index c : corners) {
    const Index next = t.corner_next(c);
    ring.push_back(t.corner_vertex(next));
    if (quads) ring.push_back(t.corner_vertex(t.corner_next(next)));
    if (boundary && c == corners.back()) ring.push_back(t.corner_vertex(t.corner_prev(c)));
  }
  return ring;
}

Vec3 apply(const Eigen::VectorXd& mask, const std::vector<Index>& ring, const std::vector<Vec3>& p) {
  Vec3 sum;
  for (std::size_t i = 0; i < ring.size(); ++i) sum += mask[static_cast<Eigen::Index>(i)] * p[static_cast<std::size_t>(ring[i])];
  return sum;
}

// The generic masks at v, when its neighbourhood matches a configuration.
struct GenericLimit {
  Vec3 position;
  std::optional<Vec3> normal;  ///< unit, oriented by the faces; nullopt without tangent masks
};

std::optional<GenericLimit> generic_limit(const MeshTopology& t, const LevelCreasing& creasing,
                                          const std::vector<Vec3>& positions, Index v, bool quads, MaskCache& cache) {
  const Vec3 p = positions[static_cast<std::size_t>(v)];
  const auto vi = static_cast<std::size_t>(v);
  const VertexRule rule = creasing.vertex_rule[vi];
  if (rule == VertexRule::corner) return GenericLimit{p, std::nullopt};  // every rule here keeps a corner
  // The canonical ring's rules: faces of the split's kind, the rule
  // constant over the levels, edges smooth or (boundary) infinitely sharp.
  bool canonical = t.ring_ordered(v) && rule == creasing.child_vertex_rule[vi];
  int sharp = 0;
  for (const Index e : t.vertex_edges(v)) {
    const double s = edge_sharpness_of(creasing, e);
    if (s >= kInfiniteSharpness) ++sharp;
    else if (s > 0.0) canonical = false;
  }
  const Index face_size = quads ? 4 : 3;
  for (const Index c : t.vertex_corners(v)) canonical = canonical && t.face_size(t.corner_face(c)) == face_size;
  const VertexKind kind = t.vertex_kind(v);
  const bool smooth_interior = kind == VertexKind::interior && rule == VertexRule::smooth && sharp == 0;
  const bool smooth_boundary = kind == VertexKind::boundary && rule == VertexRule::crease && sharp == 2 &&
                               t.vertex_face_count(v) >= 2;
  const bool interior_crease = kind == VertexKind::interior && rule == VertexRule::crease && sharp == 2;
  if (!canonical || !(smooth_interior || smooth_boundary || interior_crease)) return std::nullopt;
  if (interior_crease) {
    // The boundary configuration's mask along the curve, when it uses the
    // curve only (centre, first and last ring vertex): the same curve rules.
    const Masks& m = cache.at(Configuration::Kind::boundary, 2);
    Index ends[2] = {kInvalidIndex, kInvalidIndex};
    int n = 0;
    for (const Index e : t.vertex_edges(v))
      if (edge_sharpness_of(creasing, e) > 0.0 && n < 2) ends[n++] = t.other_vertex(e, v);
    if (!m.limit || m.limit->size() < 3) return std::nullopt;
    const Eigen::VectorXd& mask = *m.limit;
    if (mask.segment(2, mask.size() - 3).cwiseAbs().sum() > 1e-12) return std::nullopt;
    return GenericLimit{mask[0] * p + mask[1] * positions[static_cast<std::size_t>(ends[0])] +
                            mask[mask.size() - 1] * positions[static_cast<std::size_t>(ends[1])],
                        std::nullopt};
  }
  const int k = smooth_interior ? t.valence(v) : t.vertex_face_count(v);
  const Masks& m = cache.at(smooth_interior ? Configuration::Kind::interior : Configuration::Kind::boundary, k);
  const std::vector<Index> ring = canonical_ring(t, v, quads, smooth_boundary);
  if (!m.limit || static_cast<std::size_t>(m.limit->size()) != ring.size()) return std::nullopt;
  GenericLimit result{apply(*m.limit, ring, positions), std::nullopt};
  if (!m.tangents) return result;
  Vec3 normal = cross(apply((*m.tangents)[0], ring, positions), apply((*m.tangents)[1], ring, positions));
  // The masks' sign convention is arbitrary: orient by the faces.
  Vec3 faces;
  for (const Index c : t.vertex_corners(v)) {
    const Vec3 a = positions[static_cast<std::size_t>(t.corner_vertex(t.corner_next(c)))] - p;
    const Vec3 b = positions[static_cast<std::size_t>(t.corner_vertex(t.corner_prev(c)))] - p;
    faces += cross(a, b);
  }
  if (dot(normal, faces) < 0.0) normal = -1.0 * normal;
  const double length = norm(normal);
  result.normal = length > 0.0 ? (1.0 / length) * normal : Vec3{};
  return result;
}

// Refinement steps after which the closed forms apply everywhere they can:
// one where a face has another size than the split's, ceil(s) for the
// largest finite sharpness s; at most `cap`.
int levels_to_resolve(const PolygonMesh& mesh, const Scheme& scheme, int cap) {
  int levels = 0;
  const Index face_size = scheme.split == SplitRule::quad ? 4 : 3;
  for (Index f = 0; f < mesh.face_count() && levels == 0; ++f)
    if (mesh.face_size(f) != face_size) levels = 1;
  auto need = [&](double s) {
    if (s > 0.0 && s < kInfiniteSharpness) levels = std::max(levels, static_cast<int>(std::ceil(s)));
  };
  for (const CreaseTag& c : mesh.tags.creases) need(c.sharpness);
  for (const CornerTag& c : mesh.tags.corners) need(c.sharpness);
  return std::min(levels, cap);
}

}  // namespace

LimitResult limit_positions(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& options) {
  if (options.isolation_levels < 0 || options.max_resolve_levels < 0)
    throw InvalidInputError("limit: refinement levels must be >= 0");
  if (scheme.split == SplitRule::dual) return dual_limit_positions(mesh, scheme, options);
  // The closed forms are those of the standard rules. Under the
  // piecewise-smooth rules the generic masks of the modified matrices apply,
  // after at least one step: a vertex next to an extraordinary sharp vertex
  // has a modified edge point in its ring, which its configuration's matrix
  // does not describe; its vertex point one level down has none.
  const bool piecewise = options.refine.boundary_rules == BoundaryRules::piecewise_smooth;
  const bool closed_form = options.route == LimitRoute::closed_form && scheme.limit_masks != nullptr && !piecewise;
  const int levels = closed_form ? levels_to_resolve(mesh, scheme, options.max_resolve_levels)
                     : piecewise ? std::max(1, options.isolation_levels)
                                 : options.isolation_levels;
  RefineOptions check = options.refine;
  check.levels = levels;
  check_refinable(mesh, scheme, check);

  // Each input vertex is followed through the levels: the vertex point of
  // v is child F + E + v (quad split) or E + v (triangle split).
  std::vector<Index> where(static_cast<std::size_t>(mesh.vertex_count()));
  std::iota(where.begin(), where.end(), 0);
  PolygonMesh current = mesh;
  RefineOptions one = options.refine;
  one.levels = 1;
  for (int l = 0; l < levels; ++l) {
    const MeshTopology t(current);
    const Index offset = (scheme.split == SplitRule::quad ? t.face_count() : 0) + t.edge_count();
    for (Index& w : where) w += offset;
    current = refine(current, scheme, one);
  }

  const MeshTopology t(current);
  const BoundaryInterpolation boundary = options.refine.boundary.value_or(current.tags.boundary_interpolation);
  const CreaseMethod method = options.refine.crease_method.value_or(current.tags.crease_method);
  const LevelCreasing creasing = compute_creasing(current, t, boundary, method);
  std::vector<char> semi_sharp_vertex(static_cast<std::size_t>(current.vertex_count()), 0);
  for (const CornerTag& c : current.tags.corners)
    if (c.sharpness > 0.0 && c.sharpness < kInfiniteSharpness) semi_sharp_vertex[static_cast<std::size_t>(c.vertex)] = 1;
  const detail::LimitLevel level{t, creasing, current.positions, semi_sharp_vertex};
  const bool quads = scheme.split == SplitRule::quad;
  MaskCache cache(scheme, options.refine);
  LimitMasks scratch;

  LimitResult result;
  result.levels_refined = levels;
  result.positions.resize(where.size());
  result.sources.assign(where.size(), LimitSource::refined_position);
  if (options.normals) {
    result.normals.assign(where.size(), Vec3{});
    if (closed_form) result.tangents1 = result.tangents2 = result.normals;
  }
  for (std::size_t i = 0; i < where.size(); ++i) {
    const Index v = where[i];
    result.positions[i] = current.positions[static_cast<std::size_t>(v)];
    if (closed_form) {
      if (const auto limit = detail::closed_form_limit(scheme, level, v, scratch)) {
        result.positions[i] = limit->position;
        result.sources[i] = LimitSource::closed_form;
        if (!options.normals) continue;
        result.tangents1[i] = limit->tangent1;
        result.tangents2[i] = limit->tangent2;
        const Vec3 normal = cross(limit->tangent1, limit->tangent2);
        const double length = norm(normal);
        if (length > 0.0) result.normals[i] = (1.0 / length) * normal;
        continue;
      }
    }
    if (const auto limit = generic_limit(t, creasing, current.positions, v, quads, cache)) {
      result.positions[i] = limit->position;
      result.sources[i] = LimitSource::generic;
      if (options.normals && limit->normal) result.normals[i] = *limit->normal;
      continue;
    }
    ++result.approximated;
  }
  return result;
}

}  // namespace subdiv
