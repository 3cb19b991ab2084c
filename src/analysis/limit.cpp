#include "subdiv/analysis/limit.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <numbers>
#include <optional>
#include <tuple>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/dual_limit.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"

#include "../refine/piecewise_smooth.h"
#include "closed_form_limit.h"

namespace subdiv {

namespace {

// The masks of one configuration, from the analysis.
struct Masks {
  std::optional<Eigen::VectorXd> limit;
  std::optional<std::array<Eigen::VectorXd, 2>> tangents;
  /// The tangents span the tangent plane (false at a corner whose pair 1/2
  /// is not subdominant: the surface folds or flips there).
  bool normal = false;
};

// At a corner the two boundary curves give the eigenvalue 1/2 twice, their
// tangents the left eigenvectors. The basis along the curves: the first
// mask has no weight on the last ring vertex (the second boundary
// neighbour), the second none on the first; each weighs its own boundary
// neighbour 1.
std::optional<std::array<Eigen::VectorXd, 2>> corner_tangent_masks(const Eigen::MatrixXd& S) {
  const Eigen::Index n = S.rows();
  if (n < 3) return std::nullopt;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(S.transpose() - 0.5 * Eigen::MatrixXd::Identity(n, n));
  lu.setThreshold(1e-10);
  const Eigen::MatrixXd K = lu.kernel();
  if (K.cols() != 2) return std::nullopt;
  Eigen::Matrix2d A;
  A << K(1, 0), K(1, 1), K(n - 1, 0), K(n - 1, 1);
  if (std::fabs(A.determinant()) < 1e-12) return std::nullopt;
  const Eigen::Matrix2d inverse = A.inverse();
  return std::array<Eigen::VectorXd, 2>{K * inverse.col(0), K * inverse.col(1)};
}

bool same(double a, double b) { return std::fabs(a - b) <= 1e-9; }

class MaskCache {
 public:
  MaskCache(const Scheme& scheme, const RefineOptions& rules) : scheme_(scheme), rules_(rules) {}

  /// Corners: keyed by type and angle under the piecewise-smooth rules
  /// (their edge points and the flatness modification depend on them); the
  /// standard rules ignore both.
  const Masks& at(const Configuration& c) {
    const bool piecewise = rules_.boundary_rules == BoundaryRules::piecewise_smooth;
    Configuration canonical{c.kind, c.k, CornerType::convex, 0.0};
    if (c.kind == Configuration::Kind::corner && piecewise) {
      canonical.angle = c.sector_angle();
      canonical.corner = canonical.angle > std::numbers::pi ? CornerType::concave : CornerType::convex;
    }
    const auto key = std::tuple{static_cast<int>(canonical.kind), canonical.k, static_cast<int>(canonical.corner),
                                canonical.angle};
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    AnalysisOptions options;
    options.characteristic_map = false;
    options.rules = rules_;
    const ConfigurationAnalysis a = analyze(scheme_, canonical, options);
    if (a.matrix.invariant && a.matrix.rings != 1)
      throw InvalidInputError(std::string(scheme_.name) + ": limit masks over more than the one-ring are not supported yet");
    Masks masks{a.limit_mask, a.tangent_masks, a.tangent_masks.has_value()};
    if (canonical.kind == Configuration::Kind::corner && a.matrix.invariant) {
      // The pair 1/2 spans the tangent plane when it is subdominant:
      // lambda_1 = lambda_2 = 1/2 > |lambda_3|.
      masks.tangents = corner_tangent_masks(a.matrix.S);
      const auto& l = a.leading;
      masks.normal = masks.tangents && l.size() >= 4 && same(l[1].real(), 0.5) && same(l[2].real(), 0.5) &&
                     same(l[1].imag(), 0.0) && same(l[2].imag(), 0.0) && std::abs(l[3]) < 0.5 - 1e-9;
    }
    return cache_.emplace(key, std::move(masks)).first->second;
  }

 private:
  const Scheme& scheme_;
  RefineOptions rules_;
  std::map<std::tuple<int, int, int, double>, Masks> cache_;
};

// The centre and the one-ring of the sector of v whose faces are
// vertex_corners(v)[first .. first + count) (cyclically), in the order of
// the configuration's layout: counter-clockwise from the first face's
// outgoing edge; for quads the edge neighbour and then the face's opposite
// vertex of each face; in a sector bounded by sharp edges (boundary, crease,
// corner), the last face's incoming neighbour closes the list.
std::vector<Index> canonical_ring(const MeshTopology& t, Index v, bool quads, bool bounded, std::size_t first,
                                  std::size_t count) {
  std::vector<Index> ring{v};
  const auto corners = t.vertex_corners(v);
  for (std::size_t j = 0; j < count; ++j) {
    const Index c = corners[(first + j) % corners.size()];
    const Index next = t.corner_next(c);
    ring.push_back(t.corner_vertex(next));
    if (quads) ring.push_back(t.corner_vertex(t.corner_next(next)));
    if (bounded && j + 1 == count) ring.push_back(t.corner_vertex(t.corner_prev(c)));
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
  /// Oriented so that tangent1 x tangent2 points along the faces' normal;
  /// nullopt without tangent masks.
  std::optional<std::array<Vec3, 2>> tangents;
  std::optional<Vec3> normal;  ///< unit, oriented by the faces; nullopt where undefined
};

// The level data the generic masks read.
struct GenericLevel {
  const MeshTopology& t;
  const LevelCreasing& creasing;
  const std::vector<Vec3>& positions;
  const std::vector<char>& semi_sharp_vertex;
  const std::vector<double>& sector_angle;  ///< piecewise-smooth rules; else empty
  bool quads;
};

// A sector of v: faces vertex_corners(v)[first .. first + count), bounded by
// sharp edges, or all of them around a smooth vertex.
struct Sector {
  std::size_t first = 0, count = 0;
};

// The sectors of v between consecutive sharp edges (ring-ordered v).
std::vector<Sector> sharp_sectors(const GenericLevel& g, Index v) {
  const auto edges = g.t.vertex_edges(v);
  const std::size_t faces = g.t.vertex_corners(v).size();
  std::vector<std::size_t> sharp;
  for (std::size_t j = 0; j < edges.size(); ++j)
    if (edge_sharpness_of(g.creasing, edges[j]) >= kInfiniteSharpness) sharp.push_back(j);
  std::vector<Sector> sectors;
  if (g.t.vertex_kind(v) == VertexKind::boundary) {
    // e_0 .. e_k, face j between e_j and e_{j+1}.
    for (std::size_t i = 0; i + 1 < sharp.size(); ++i) sectors.push_back({sharp[i], sharp[i + 1] - sharp[i]});
  } else {
    for (std::size_t i = 0; i < sharp.size(); ++i) {
      const std::size_t a = sharp[i], b = sharp[(i + 1) % sharp.size()];
      sectors.push_back({a, (b + faces - a - 1) % faces + 1});
    }
  }
  return sectors;
}

// Position, tangents and normal from one configuration's masks on a ring;
// `sector` gives the faces that orient the normal.
GenericLimit from_masks(const GenericLevel& g, Index v, const Masks& m, const std::vector<Index>& ring, Sector sector) {
  GenericLimit result{apply(*m.limit, ring, g.positions), std::nullopt, std::nullopt};
  if (!m.tangents) return result;
  Vec3 t1 = apply((*m.tangents)[0], ring, g.positions), t2 = apply((*m.tangents)[1], ring, g.positions);
  Vec3 normal = cross(t1, t2);
  // The masks' sign convention is arbitrary: orient by the faces.
  const Vec3 p = g.positions[static_cast<std::size_t>(v)];
  const auto corners = g.t.vertex_corners(v);
  Vec3 faces;
  for (std::size_t j = 0; j < sector.count; ++j) {
    const Index c = corners[(sector.first + j) % corners.size()];
    const Vec3 a = g.positions[static_cast<std::size_t>(g.t.corner_vertex(g.t.corner_next(c)))] - p;
    const Vec3 b = g.positions[static_cast<std::size_t>(g.t.corner_vertex(g.t.corner_prev(c)))] - p;
    faces += cross(a, b);
  }
  if (dot(normal, faces) < 0.0) {
    normal = -1.0 * normal;
    t2 = -1.0 * t2;
  }
  result.tangents = std::array{t1, t2};
  const double length = norm(normal);
  if (m.normal && length > 0.0) result.normal = (1.0 / length) * normal;
  return result;
}

std::optional<GenericLimit> generic_limit(const GenericLevel& g, Index v, MaskCache& cache) {
  const MeshTopology& t = g.t;
  const Vec3 p = g.positions[static_cast<std::size_t>(v)];
  const auto vi = static_cast<std::size_t>(v);
  const VertexRule rule = g.creasing.vertex_rule[vi];
  // The canonical ring's rules: faces of the split's kind, the rule
  // constant over the levels, edges smooth or infinitely sharp.
  bool canonical = t.ring_ordered(v) && rule == g.creasing.child_vertex_rule[vi] && !g.semi_sharp_vertex[vi];
  int sharp = 0;
  for (const Index e : t.vertex_edges(v)) {
    const double s = edge_sharpness_of(g.creasing, e);
    if (s >= kInfiniteSharpness) ++sharp;
    else if (s > 0.0) canonical = false;
  }
  const Index face_size = g.quads ? 4 : 3;
  for (const Index c : t.vertex_corners(v)) canonical = canonical && t.face_size(t.corner_face(c)) == face_size;
  const VertexKind kind = t.vertex_kind(v);
  if (rule == VertexRule::corner) {
    // Every rule here keeps an infinitely sharp corner. Its tangents: the
    // corner configuration's pair 1/2 on one sector (a boundary corner's
    // only one, an interior corner's first), the sector angle as the rules
    // give it.
    // The flatness modification applies at boundary corners of one sector
    // only: a concave sector beside others matches no configuration.
    GenericLimit corner{p, std::nullopt, std::nullopt};
    if (!canonical || sharp < 2 || (kind != VertexKind::boundary && kind != VertexKind::interior)) return corner;
    const Sector sector = sharp_sectors(g, v).front();
    Configuration c{Configuration::Kind::corner, static_cast<int>(sector.count), CornerType::convex, 0.0};
    if (!g.sector_angle.empty()) c.angle = g.sector_angle[vi];
    if (c.angle > std::numbers::pi) c.corner = CornerType::concave;
    if (c.corner == CornerType::concave && !(kind == VertexKind::boundary && sharp == 2)) return corner;
    const Masks& m = cache.at(c);
    const std::vector<Index> ring = canonical_ring(t, v, g.quads, true, sector.first, sector.count);
    if (!m.limit || !m.tangents || static_cast<std::size_t>(m.limit->size()) != ring.size()) return corner;
    GenericLimit result = from_masks(g, v, m, ring, sector);
    result.position = p;
    return result;
  }
  const bool smooth_interior = kind == VertexKind::interior && rule == VertexRule::smooth && sharp == 0;
  const bool smooth_boundary = kind == VertexKind::boundary && rule == VertexRule::crease && sharp == 2 &&
                               t.vertex_face_count(v) >= 2;
  const bool interior_crease = kind == VertexKind::interior && rule == VertexRule::crease && sharp == 2;
  if (!canonical || !(smooth_interior || smooth_boundary || interior_crease)) return std::nullopt;
  if (interior_crease) {
    // Each sector of a crease evolves as a boundary fan with its faces (the
    // crease and boundary rules are the same curve rules, and the edge
    // points of a sector read its faces only): the first sector with two or
    // more faces gives the limit along the curve, the tangent along it and
    // that sector's cross tangent.
    for (const Sector sector : sharp_sectors(g, v)) {
      if (sector.count < 2) continue;
      const Masks& m = cache.at({Configuration::Kind::boundary, static_cast<int>(sector.count)});
      const std::vector<Index> ring = canonical_ring(t, v, g.quads, true, sector.first, sector.count);
      if (!m.limit || static_cast<std::size_t>(m.limit->size()) != ring.size()) return std::nullopt;
      // The position reads the curve only (centre, first and last ring vertex).
      const Eigen::VectorXd& mask = *m.limit;
      if (mask.segment(2, mask.size() - 3).cwiseAbs().sum() > 1e-12) return std::nullopt;
      return from_masks(g, v, m, ring, sector);
    }
    return std::nullopt;
  }
  const int k = smooth_interior ? t.valence(v) : t.vertex_face_count(v);
  const Masks& m = cache.at({smooth_interior ? Configuration::Kind::interior : Configuration::Kind::boundary, k});
  const Sector all{0, t.vertex_corners(v).size()};
  const std::vector<Index> ring = canonical_ring(t, v, g.quads, smooth_boundary, all.first, all.count);
  if (!m.limit || static_cast<std::size_t>(m.limit->size()) != ring.size()) return std::nullopt;
  return from_masks(g, v, m, ring, all);
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
  if (!is_primal(scheme.split))
    throw InvalidInputError(std::string(scheme.name) + ": no limit positions for the " + to_string(scheme.split) +
                            " (its configurations repeat only every two steps)");
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
  const std::vector<double> sector_angle =
      piecewise ? detail::sector_angles(current, t, creasing) : std::vector<double>{};
  const GenericLevel generic{t, creasing, current.positions, semi_sharp_vertex, sector_angle, quads};
  MaskCache cache(scheme, options.refine);
  LimitMasks scratch;

  LimitResult result;
  result.levels_refined = levels;
  result.positions.resize(where.size());
  result.sources.assign(where.size(), LimitSource::refined_position);
  if (options.normals) {
    result.normals.assign(where.size(), Vec3{});
    result.tangents1 = result.tangents2 = result.normals;
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
    if (const auto limit = generic_limit(generic, v, cache)) {
      result.positions[i] = limit->position;
      result.sources[i] = LimitSource::generic;
      if (!options.normals) continue;
      if (limit->normal) result.normals[i] = *limit->normal;
      if (limit->tangents) {
        result.tangents1[i] = (*limit->tangents)[0];
        result.tangents2[i] = (*limit->tangents)[1];
      }
      continue;
    }
    ++result.approximated;
  }
  return result;
}

}  // namespace subdiv
