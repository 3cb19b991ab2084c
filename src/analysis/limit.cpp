#include "subdiv/analysis/limit.h"

#include <cmath>
#include <map>
#include <numeric>
#include <optional>

#include "subdiv/analysis/analyze.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"

namespace subdiv {

namespace {

// The masks of one configuration, from the analysis.
struct Masks {
  std::optional<Eigen::VectorXd> limit;
  std::optional<std::array<Eigen::VectorXd, 2>> tangents;
};

class MaskCache {
 public:
  explicit MaskCache(const Scheme& scheme) : scheme_(scheme) {}

  const Masks& at(Configuration::Kind kind, int k) {
    const auto key = std::pair{static_cast<int>(kind), k};
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    AnalysisOptions options;
    options.characteristic_map = false;
    const ConfigurationAnalysis a = analyze(scheme_, {kind, k, CornerType::convex}, options);
    if (a.matrix.invariant && a.matrix.rings != 1)
      throw InvalidInputError(std::string(scheme_.name) + ": limit masks over more than the one-ring are not supported yet");
    return cache_.emplace(key, Masks{a.limit_mask, a.tangent_masks}).first->second;
  }

 private:
  const Scheme& scheme_;
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

}  // namespace

LimitResult limit_positions(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& options) {
  if (options.isolation_levels < 0) throw InvalidInputError("limit: isolation levels must be >= 0");
  RefineOptions check = options.refine;
  check.levels = options.isolation_levels;
  check_refinable(mesh, scheme, check);

  // Each input vertex is followed through the levels: the vertex point of
  // v is child F + E + v (quad split) or E + v (triangle split).
  std::vector<Index> where(static_cast<std::size_t>(mesh.vertex_count()));
  std::iota(where.begin(), where.end(), 0);
  PolygonMesh current = mesh;
  RefineOptions one = options.refine;
  one.levels = 1;
  for (int l = 0; l < options.isolation_levels; ++l) {
    const MeshTopology t(current);
    const Index offset = (scheme.split == SplitRule::quad ? t.face_count() : 0) + t.edge_count();
    for (Index& w : where) w += offset;
    current = refine(current, scheme, one);
  }

  const MeshTopology t(current);
  const BoundaryInterpolation boundary = options.refine.boundary.value_or(current.tags.boundary_interpolation);
  const CreaseMethod method = options.refine.crease_method.value_or(current.tags.crease_method);
  const LevelCreasing creasing = compute_creasing(current, t, boundary, method);
  const bool quads = scheme.split == SplitRule::quad;
  const Index face_size = quads ? 4 : 3;
  MaskCache cache(scheme);

  LimitResult result;
  result.positions.resize(where.size());
  if (options.normals) result.normals.assign(where.size(), Vec3{});
  for (std::size_t i = 0; i < where.size(); ++i) {
    const Index v = where[i];
    const Vec3 p = current.positions[static_cast<std::size_t>(v)];
    result.positions[i] = p;
    const auto vi = static_cast<std::size_t>(v);
    const VertexRule rule = creasing.vertex_rule[vi];
    if (rule == VertexRule::corner) continue;  // every rule here keeps a corner where it is
    // The canonical ring's rules: faces of the split's kind, the rule
    // constant over the levels, edges smooth or (boundary) infinitely sharp.
    bool canonical = t.ring_ordered(v) && rule == creasing.child_vertex_rule[vi];
    int sharp = 0;
    for (const Index e : t.vertex_edges(v)) {
      const double s = edge_sharpness_of(creasing, e);
      if (s >= kInfiniteSharpness) ++sharp;
      else if (s > 0.0) canonical = false;
    }
    for (const Index c : t.vertex_corners(v)) canonical = canonical && t.face_size(t.corner_face(c)) == face_size;
    const VertexKind kind = t.vertex_kind(v);
    const bool smooth_interior = kind == VertexKind::interior && rule == VertexRule::smooth && sharp == 0;
    const bool smooth_boundary = kind == VertexKind::boundary && rule == VertexRule::crease && sharp == 2 &&
                                 t.vertex_face_count(v) >= 2;
    const bool interior_crease = kind == VertexKind::interior && rule == VertexRule::crease && sharp == 2;
    if (!canonical || !(smooth_interior || smooth_boundary || interior_crease)) {
      ++result.approximated;
      continue;
    }
    if (interior_crease) {
      // The boundary configuration's mask along the curve, when it uses the
      // curve only (centre, first and last ring vertex): the same curve rules.
      const Masks& m = cache.at(Configuration::Kind::boundary, 2);
      const auto [a, b] = [&] {
        Index found[2] = {kInvalidIndex, kInvalidIndex};
        int n = 0;
        for (const Index e : t.vertex_edges(v))
          if (edge_sharpness_of(creasing, e) > 0.0 && n < 2) found[n++] = t.other_vertex(e, v);
        return std::pair{found[0], found[1]};
      }();
      if (!m.limit || m.limit->size() < 3) {
        ++result.approximated;
        continue;
      }
      const Eigen::VectorXd& mask = *m.limit;
      const double inner = mask.segment(2, mask.size() - 3).cwiseAbs().sum();
      if (inner > 1e-12) {
        ++result.approximated;
        continue;
      }
      result.positions[i] = mask[0] * p + mask[1] * current.positions[static_cast<std::size_t>(a)] +
                            mask[mask.size() - 1] * current.positions[static_cast<std::size_t>(b)];
      continue;
    }
    const int k = smooth_interior ? t.valence(v) : t.vertex_face_count(v);
    const Masks& m = cache.at(smooth_interior ? Configuration::Kind::interior : Configuration::Kind::boundary, k);
    const std::vector<Index> ring = canonical_ring(t, v, quads, smooth_boundary);
    if (!m.limit || static_cast<std::size_t>(m.limit->size()) != ring.size()) {
      ++result.approximated;
      continue;
    }
    result.positions[i] = apply(*m.limit, ring, current.positions);
    if (!options.normals || !m.tangents) continue;
    Vec3 normal = cross(apply((*m.tangents)[0], ring, current.positions), apply((*m.tangents)[1], ring, current.positions));
    // The masks' sign convention is arbitrary: orient by the faces.
    Vec3 faces;
    for (const Index c : t.vertex_corners(v)) {
      const Vec3 a = current.positions[static_cast<std::size_t>(t.corner_vertex(t.corner_next(c)))] - p;
      const Vec3 b = current.positions[static_cast<std::size_t>(t.corner_vertex(t.corner_prev(c)))] - p;
      faces += cross(a, b);
    }
    if (dot(normal, faces) < 0.0) normal = -1.0 * normal;
    const double length = norm(normal);
    if (length > 0.0) result.normals[i] = (1.0 / length) * normal;
  }
  return result;
}

}  // namespace subdiv
