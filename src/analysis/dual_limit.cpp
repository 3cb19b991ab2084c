// Doo-Sabin (dual split) limit positions: the limit of each vertex's V-face
// (src/analysis/dual_limit.h; docs/depth.md, "Doo-Sabin").

#include "analysis/dual_limit.h"

#include <array>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "subdiv/analysis/analyze.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/core/error.h"

namespace subdiv {

std::vector<Index> face_neighbourhood(const MeshTopology& t, Index f, bool& regular) {
  const auto face = t.face_vertices(f);
  std::vector<Index> out(face.begin(), face.end());
  regular = true;
  const auto listed = [&](Index w) { return std::find(out.begin(), out.end(), w) != out.end(); };
  const Index first = t.face_first_corner(f);
  for (Index c = first; c < first + t.face_size(f); ++c) {
    const Index w = t.corner_vertex(c);
    const auto corners = t.vertex_corners(w);
    regular = regular && t.vertex_kind(w) == VertexKind::interior && corners.size() == 4;
    const auto at = std::find(corners.begin(), corners.end(), c);
    if (at == corners.end()) {  // not ring-ordered here
      regular = false;
      continue;
    }
    const auto start = static_cast<std::size_t>(at - corners.begin());
    for (std::size_t i = 1; i < corners.size(); ++i) {
      const Index g = corners[(start + i) % corners.size()];
      const Index gf = t.corner_face(g);
      regular = regular && t.face_size(gf) == 4;
      for (Index n = t.corner_next(g); n != g; n = t.corner_next(n))
        if (!listed(t.corner_vertex(n))) out.push_back(t.corner_vertex(n));
    }
  }
  regular = regular && out.size() == 4 * face.size();
  return out;
}

namespace {

constexpr double kLayoutTolerance = 1e-9;
// Mask weights below this count as zero (the eigenvector is computed to
// about 1e-12 and normalised to sum 1).
constexpr double kZeroWeight = 1e-10;

struct DualMasks {
  /// Limit and tangent masks in face_neighbourhood() order (4k entries).
  Eigen::VectorXd limit;
  bool has_tangents = false;
  Eigen::VectorXd tangent1, tangent2;
  /// Whether every mask is zero off the k-gon: then the face part alone is
  /// the limit, whatever the ring.
  bool face_only = false;
};

class DualMaskCache {
 public:
  DualMaskCache(const Scheme& scheme, const RefineOptions& rules) : scheme_(scheme), rules_(rules) {}

  const DualMasks& at(int k) {
    if (auto it = cache_.find(k); it != cache_.end()) return it->second;
    AnalysisOptions options;
    options.characteristic_map = false;
    options.rules = rules_;
    const Configuration c{Configuration::Kind::interior, k, CornerType::convex};
    const ConfigurationAnalysis a = analyze(scheme_, c, options);
    if (!a.limit_mask || !a.matrix.invariant)
      throw InvalidInputError(std::string(scheme_.name) + ": the analysis of the extraordinary face of " +
                              std::to_string(k) + " sides gives no limit mask");
    // Match the layout's neighbourhood (sorted by ring, then angle) to the
    // combinatorial order: walk the layout's own centre face the same way
    // and find each vertex's layout point.
    const RingMesh ring = ring_mesh(SplitRule::dual, c, a.matrix.rings);
    const MeshTopology t(ring.mesh);
    bool regular = false;
    const std::vector<Index> walk = face_neighbourhood(t, ring.centre_face, regular);
    const auto n = static_cast<Eigen::Index>(a.matrix.layout.size());
    if (!regular || static_cast<Eigen::Index>(walk.size()) != n || a.limit_mask->size() != n)
      throw InvalidInputError(std::string(scheme_.name) + ": the layout of the extraordinary face of " +
                              std::to_string(k) + " sides is not the k-gon and its ring of quads");
    std::vector<Eigen::Index> column(walk.size());
    for (std::size_t i = 0; i < walk.size(); ++i) {
      const Vec3 p = ring.mesh.positions[static_cast<std::size_t>(walk[i])];
      Eigen::Index found = -1;
      for (Eigen::Index j = 0; j < n; ++j)
        if (norm(a.matrix.layout[static_cast<std::size_t>(j)] - p) < kLayoutTolerance) found = j;
      if (found < 0)
        throw InvalidInputError(std::string(scheme_.name) + ": no layout point for a neighbourhood vertex of the " +
                                std::to_string(k) + "-gon");
      column[i] = found;
    }
    const auto reorder = [&](const Eigen::VectorXd& mask) {
      Eigen::VectorXd out(n);
      for (Eigen::Index i = 0; i < n; ++i) out[i] = mask[column[static_cast<std::size_t>(i)]];
      return out;
    };
    DualMasks m;
    m.limit = reorder(*a.limit_mask);
    const auto ring_free = [&](const Eigen::VectorXd& mask) {
      return mask.tail(n - k).cwiseAbs().maxCoeff() <= kZeroWeight * mask.head(k).cwiseAbs().maxCoeff();
    };
    m.face_only = ring_free(m.limit);
    if (a.tangent_masks) {
      m.has_tangents = true;
      m.tangent1 = reorder((*a.tangent_masks)[0]);
      m.tangent2 = reorder((*a.tangent_masks)[1]);
      m.face_only = m.face_only && ring_free(m.tangent1) && ring_free(m.tangent2);
    }
    return cache_.emplace(k, std::move(m)).first->second;
  }

 private:
  const Scheme& scheme_;
  RefineOptions rules_;
  std::map<int, DualMasks> cache_;
};

Vec3 apply(const Eigen::VectorXd& mask, const std::vector<Index>& vertices, std::size_t count,
           const std::vector<Vec3>& p) {
  Vec3 sum;
  for (std::size_t i = 0; i < count; ++i)
    sum += mask[static_cast<Eigen::Index>(i)] * p[static_cast<std::size_t>(vertices[i])];
  return sum;
}

}  // namespace

LimitResult dual_limit_positions(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& options) {
  if (scheme.split != SplitRule::dual)
    throw InvalidInputError(std::string(scheme.name) + ": dual limit positions need a dual-split scheme");
  RefineOptions one = options.refine;
  one.levels = 1;
  one.on_level = nullptr;
  check_refinable(mesh, scheme, one);
  const PolygonMesh child = refine(mesh, scheme, one);
  const MeshTopology parent(mesh);
  const MeshTopology t(child);
  DualMaskCache cache(scheme, options.refine);
  const std::array<double, 3> boundary = boundary_vertex_limit(scheme);  // (a, v, b) along the boundary

  LimitResult result;
  result.levels_refined = 1;
  result.positions = mesh.positions;
  result.sources.assign(mesh.positions.size(), LimitSource::refined_position);
  if (options.normals) result.normals.assign(mesh.positions.size(), Vec3{});
  // Child faces: [F-faces | E-faces | V-faces of the vertices that have one]
  // (src/topology/dual_split.cpp).
  Index v_face = parent.face_count() + parent.edge_count();
  for (Index v = 0; v < parent.vertex_count(); ++v) {
    const auto vi = static_cast<std::size_t>(v);
    const auto faces = static_cast<int>(parent.vertex_face_count(v));
    const VertexKind kind = parent.vertex_kind(v);
    if (faces == 0) {
      ++result.approximated;
      continue;
    }
    if (kind == VertexKind::boundary) {
      ++v_face;
      const auto edges = parent.vertex_edges(v);
      const Vec3 a = mesh.positions[static_cast<std::size_t>(parent.other_vertex(edges.front(), v))];
      const Vec3 b = mesh.positions[static_cast<std::size_t>(parent.other_vertex(edges.back(), v))];
      result.positions[vi] = boundary[0] * a + boundary[1] * mesh.positions[vi] + boundary[2] * b;
      result.sources[vi] = LimitSource::closed_form;
      continue;
    }
    if (!dual_split_has_v_face(parent, v)) {
      ++result.approximated;
      continue;
    }
    const Index f = v_face++;
    bool regular = false;
    const std::vector<Index> around = face_neighbourhood(t, f, regular);
    const DualMasks& m = cache.at(faces);
    const std::size_t count = regular ? around.size() : static_cast<std::size_t>(faces);
    if (!regular && !m.face_only) {
      ++result.approximated;
      continue;
    }
    result.positions[vi] = apply(m.limit, around, count, child.positions);
    result.sources[vi] = LimitSource::generic;
    if (!options.normals || !m.has_tangents) continue;
    Vec3 normal = cross(apply(m.tangent1, around, count, child.positions),
                        apply(m.tangent2, around, count, child.positions));
    // Orient by the V-face (Newell's normal).
    Vec3 face_normal;
    for (std::size_t i = 0; i < static_cast<std::size_t>(faces); ++i)
      face_normal += cross(child.positions[static_cast<std::size_t>(around[i])],
                           child.positions[static_cast<std::size_t>(around[(i + 1) % static_cast<std::size_t>(faces)])]);
    if (dot(normal, face_normal) < 0.0) normal = -1.0 * normal;
    const double length = norm(normal);
    result.normals[vi] = length > 0.0 ? (1.0 / length) * normal : Vec3{};
  }
  return result;
}

}  // namespace subdiv
