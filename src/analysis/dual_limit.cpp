// Doo-Sabin (dual split) limit positions: the limit of each vertex's V-face
// (src/analysis/dual_limit.h; docs/depth.md, "Doo-Sabin").

#include "analysis/dual_limit.h"

#include <array>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
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

// The canonical neighbourhood of an extraordinary face: the analysis's ring
// mesh, the faces within its layout, and the order in which walk() visits
// their vertices.
struct FaceNeighbourhood {
  std::optional<MeshTopology> topology;  ///< always set (MeshTopology has no empty state)
  Index first = kInvalidIndex;  ///< the centre face's first corner
  std::vector<char> inside;     ///< per face: every vertex is a layout point
};

// Walks the faces of `n` inside its layout from its centre face, in lockstep
// with mesh `t` from corner `start` of a mesh face, crossing each edge into
// the next inside face; returns the mesh vertex of each canonical vertex in
// the order first seen (the centre face's corners first), and the canonical
// vertices in `order`. nullopt where the mesh differs: a face size, a
// missing or flipped face across an edge, two canonical vertices on one
// mesh vertex or the reverse, or an inner canonical vertex (all of whose
// faces are inside) with another face count.
std::optional<std::vector<Index>> walk(const FaceNeighbourhood& n, const MeshTopology& t, Index start,
                                       std::vector<Index>* order = nullptr) {
  const MeshTopology& T = *n.topology;
  std::vector<Index> image(static_cast<std::size_t>(T.vertex_count()), kInvalidIndex);
  std::vector<Index> face_image(static_cast<std::size_t>(T.face_count()), kInvalidIndex);
  std::vector<Index> seen;
  std::vector<std::pair<Index, Index>> queue{{n.first, start}};
  face_image[static_cast<std::size_t>(T.corner_face(n.first))] = t.corner_face(start);
  for (std::size_t q = 0; q < queue.size(); ++q) {
    auto [cc, mc] = queue[q];
    const Index size = T.face_size(T.corner_face(cc));
    if (t.face_size(t.corner_face(mc)) != size) return std::nullopt;
    for (Index i = 0; i < size; ++i, cc = T.corner_next(cc), mc = t.corner_next(mc)) {
      const Index u = T.corner_vertex(cc);
      Index& w = image[static_cast<std::size_t>(u)];
      if (w == kInvalidIndex) {
        w = t.corner_vertex(mc);
        seen.push_back(u);
      } else if (w != t.corner_vertex(mc)) {
        return std::nullopt;
      }
      const Index across = T.corner_across(cc);
      if (across == kInvalidIndex || !n.inside[static_cast<std::size_t>(T.corner_face(across))]) continue;
      const Index mesh_across = t.corner_across(mc);
      if (mesh_across == kInvalidIndex || t.corner_vertex(mesh_across) != t.corner_vertex(t.corner_next(mc)))
        return std::nullopt;
      Index& mapped = face_image[static_cast<std::size_t>(T.corner_face(across))];
      if (mapped == kInvalidIndex) {
        mapped = t.corner_face(mesh_across);
        queue.emplace_back(across, mesh_across);
      } else if (mapped != t.corner_face(mesh_across)) {
        return std::nullopt;
      }
    }
  }
  std::vector<Index> vertices;
  for (const Index u : seen) vertices.push_back(image[static_cast<std::size_t>(u)]);
  std::vector<Index> sorted = vertices;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return std::nullopt;
  for (const Index u : seen) {
    bool inner = T.vertex_kind(u) == VertexKind::interior;
    for (const Index c : T.vertex_corners(u)) inner = inner && n.inside[static_cast<std::size_t>(T.corner_face(c))];
    if (inner && t.vertex_corners(image[static_cast<std::size_t>(u)]).size() != T.vertex_corners(u).size())
      return std::nullopt;
  }
  if (order) *order = std::move(seen);
  return vertices;
}

struct DualMasks {
  FaceNeighbourhood neighbourhood;
  /// Limit and tangent masks in walk() order (the k-gon's corners first).
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
    options.regular_rules = false;  // the masks alone
    options.rules = rules_;
    const Configuration c{Configuration::Kind::interior, k, CornerType::convex};
    const ConfigurationAnalysis a = analyze(scheme_, c, options);
    if (!a.limit_mask || !a.matrix.invariant)
      throw InvalidInputError(std::string(scheme_.name) + ": the analysis of the extraordinary face of " +
                              std::to_string(k) + " sides gives no limit mask");
    // The layout's neighbourhood (sorted by ring, then angle) in walk()
    // order: walk the ring mesh over itself and find each vertex's layout
    // point.
    const RingMesh ring = ring_mesh(SplitRule::dual, c, a.matrix.rings);
    DualMasks m;
    FaceNeighbourhood& n = m.neighbourhood;
    n.topology.emplace(ring.mesh);
    const MeshTopology& T = *n.topology;
    n.first = T.face_first_corner(ring.centre_face);
    const auto n_columns = static_cast<Eigen::Index>(a.matrix.layout.size());
    auto column_of = [&](Index u) {
      const Vec3 p = ring.mesh.positions[static_cast<std::size_t>(u)];
      for (Eigen::Index j = 0; j < n_columns; ++j)
        if (norm(a.matrix.layout[static_cast<std::size_t>(j)] - p) < kLayoutTolerance) return j;
      return Eigen::Index{-1};
    };
    n.inside.assign(static_cast<std::size_t>(T.face_count()), 1);
    for (Index f = 0; f < T.face_count(); ++f)
      for (const Index u : T.face_vertices(f)) n.inside[static_cast<std::size_t>(f)] &= column_of(u) >= 0 ? 1 : 0;
    std::vector<Index> order;
    if (!walk(n, T, n.first, &order) || static_cast<Eigen::Index>(order.size()) != n_columns ||
        a.limit_mask->size() != n_columns)
      throw InvalidInputError(std::string(scheme_.name) + ": the layout of the extraordinary face of " +
                              std::to_string(k) + " sides is not a neighbourhood of faces around it");
    std::vector<Eigen::Index> column;
    for (const Index u : order) column.push_back(column_of(u));
    const auto reorder = [&](const Eigen::VectorXd& mask) {
      Eigen::VectorXd out(n_columns);
      for (Eigen::Index i = 0; i < n_columns; ++i) out[i] = mask[column[static_cast<std::size_t>(i)]];
      return out;
    };
    m.limit = reorder(*a.limit_mask);
    const auto ring_free = [&](const Eigen::VectorXd& mask) {
      return mask.tail(n_columns - k).cwiseAbs().maxCoeff() <= kZeroWeight * mask.head(k).cwiseAbs().maxCoeff();
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
  const bool midedge = scheme.split == SplitRule::midedge;
  if (scheme.split != SplitRule::dual && !midedge)
    throw InvalidInputError(std::string(scheme.name) + ": dual limit positions need a dual or midedge split");
  RefineOptions one = options.refine;
  one.levels = 1;
  one.on_level = nullptr;
  check_refinable(mesh, scheme, one);
  const MeshTopology parent(mesh);
  // Levels 1, 2, ...: a V-face's descendants keep its index (a face's F-face
  // child is numbered as the face), and deeper levels separate the
  // extraordinary faces until a wide neighbourhood matches. Made on demand,
  // up to 1 + isolation_levels and the face budget.
  std::vector<PolygonMesh> levels{refine(mesh, scheme, one)};
  std::vector<MeshTopology> topologies{MeshTopology(levels.front())};
  auto deeper = [&]() {
    const int made = static_cast<int>(levels.size());
    if (made > options.isolation_levels || 4 * static_cast<std::int64_t>(levels.back().corner_count()) >
                                               options.max_resolve_faces)
      return false;
    RefineOptions next = one;
    next.start_level = options.refine.start_level + made;
    levels.push_back(refine(levels.back(), scheme, next));
    topologies.emplace_back(levels.back());
    return true;
  };
  DualMaskCache cache(scheme, options.refine);
  // (a, v, b) along the boundary, where the boundary follows a curve scheme
  // (Doo-Sabin's Chaikin); elsewhere boundary vertices are not resolved.
  std::optional<std::array<double, 3>> boundary;
  if (scheme.masks.boundary_curve) boundary = boundary_vertex_limit(scheme);

  LimitResult result;
  result.levels_refined = 1;
  result.positions = mesh.positions;
  result.sources.assign(mesh.positions.size(), LimitSource::refined_position);
  if (options.normals) result.normals.assign(mesh.positions.size(), Vec3{});
  // Child faces: [F-faces | E-faces | V-faces of the vertices that have one]
  // (src/topology/dual_split.cpp); the midedge split has no E-faces, and
  // V-faces at vertices of three or more edges (midedge_split.cpp).
  Index v_face = parent.face_count() + (midedge ? 0 : parent.edge_count());
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
      if (!boundary) {
        ++result.approximated;
        continue;
      }
      const auto edges = parent.vertex_edges(v);
      const Vec3 a = mesh.positions[static_cast<std::size_t>(parent.other_vertex(edges.front(), v))];
      const Vec3 b = mesh.positions[static_cast<std::size_t>(parent.other_vertex(edges.back(), v))];
      result.positions[vi] = (*boundary)[0] * a + (*boundary)[1] * mesh.positions[vi] + (*boundary)[2] * b;
      result.sources[vi] = LimitSource::closed_form;
      continue;
    }
    if (midedge ? parent.vertex_edges(v).size() < 3 : !dual_split_has_v_face(parent, v)) {
      ++result.approximated;
      continue;
    }
    const Index f = v_face++;
    const DualMasks& m = cache.at(faces);
    std::size_t level = 0;
    auto matched = walk(m.neighbourhood, topologies[0], topologies[0].face_first_corner(f));
    while (!matched && !m.face_only && (level + 1 < levels.size() || deeper())) {
      ++level;
      matched = walk(m.neighbourhood, topologies[level], topologies[level].face_first_corner(f));
    }
    if (!matched && !m.face_only) {
      ++result.approximated;
      continue;
    }
    if (!matched) level = 0;
    const MeshTopology& t = topologies[level];
    const PolygonMesh& child = levels[level];
    result.levels_refined = std::max(result.levels_refined, static_cast<int>(level) + 1);
    std::vector<Index> around;  // the k-gon alone where only its part is read
    if (matched) around = *matched;
    else around.assign(t.face_vertices(f).begin(), t.face_vertices(f).end());
    const std::size_t count = matched ? around.size() : static_cast<std::size_t>(faces);
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
