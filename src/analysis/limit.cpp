#include "subdiv/analysis/limit.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <numbers>
#include <optional>
#include <tuple>

#include "subdiv/analysis/analyze.h"
#include "analysis/dual_limit.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/refine/hierarchy.h"

#include "../refine/piecewise_smooth.h"
#include "closed_form_limit.h"
#include "local_refinement.h"

namespace subdiv {

namespace {

// The canonical neighbourhood the masks are over: the configuration's ring
// mesh, built as the local subdivision matrix built it, with the matrix's
// columns located in it by their layout points.
struct Neighbourhood {
  int rings = 1;
  MeshTopology topology;
  /// Matrix column a -> ring-mesh vertex.
  std::vector<Index> column_vertex;
  /// Per ring-mesh vertex: its face ring, -1 outside the neighbourhood.
  std::vector<int> ring_of;
  /// Per ring-mesh face: within `rings` face rings (it has a vertex of ring
  /// < rings: an inner vertex).
  std::vector<char> face_inside;
  /// Per ring-mesh vertex: its vertex rule, for the mesh's inner vertices to
  /// match.
  std::vector<VertexRule> rule;
  /// The centre's corner in the first face of sector 0 (outgoing edge along
  /// the first ray).
  Index start = kInvalidIndex;
  /// The matrix: row a is column a's child one level down.
  Eigen::MatrixXd S;
  /// Per column: the ring-mesh element whose child is column a's image one
  /// level down (at half its grid point).
  std::vector<ImageParent> parent;

  bool inner(Index u) const {
    const int r = ring_of[static_cast<std::size_t>(u)];
    return r >= 0 && r < rings;
  }
};

// The masks of one configuration, from the analysis.
struct Masks {
  std::optional<Eigen::VectorXd> limit;
  std::optional<std::array<Eigen::VectorXd, 2>> tangents;
  /// The tangents span the tangent plane (false at a corner whose pair 1/2
  /// is not subdominant: the surface folds or flips there).
  bool normal = false;
  /// Where the masks are over; absent when there are no masks.
  std::optional<Neighbourhood> neighbourhood;
};

// The neighbourhood of matrix m in its ring mesh (the same construction
// local_subdivision_matrix uses), the vertex rules under the level's
// boundary interpolation and creasing method.
Neighbourhood canonical_neighbourhood(SplitRule split, const LocalSubdivisionMatrix& m, BoundaryInterpolation boundary,
                                      CreaseMethod method) {
  const RingMesh ring = analysis_ring_mesh(split, m.configuration, ring_mesh_size(m.rings));
  Neighbourhood n{m.rings, MeshTopology(ring.mesh), {}, {}, {}, {}, kInvalidIndex, {}, {}};
  const MeshTopology& t = n.topology;
  const auto& positions = ring.mesh.positions;
  n.ring_of.assign(positions.size(), -1);
  for (std::size_t a = 0; a < m.layout.size(); ++a) {
    Index found = kInvalidIndex;
    for (std::size_t v = 0; v < positions.size() && found == kInvalidIndex; ++v)
      if (norm(positions[v] - m.layout[a]) < 1e-9) found = static_cast<Index>(v);
    if (found == kInvalidIndex)
      throw InvalidInputError(m.configuration.name() + ": a neighbourhood point is not a ring-mesh vertex");
    n.column_vertex.push_back(found);
    n.ring_of[static_cast<std::size_t>(found)] = m.ring_of[a];
  }
  n.face_inside.assign(static_cast<std::size_t>(t.face_count()), 0);
  for (Index f = 0; f < t.face_count(); ++f)
    for (const Index v : t.face_vertices(f)) n.face_inside[static_cast<std::size_t>(f)] |= n.inner(v) ? 1 : 0;
  for (const Index c : t.vertex_corners(ring.centre)) {
    const Vec3 p = positions[static_cast<std::size_t>(t.corner_vertex(t.corner_next(c)))];
    if (norm(p - Vec3{1.0, 0.0, 0.0}) < 1e-9) n.start = c;
  }
  if (n.start == kInvalidIndex) throw InvalidInputError(m.configuration.name() + ": no face along the first ray");
  n.rule = compute_creasing(ring.mesh, t, boundary, method).vertex_rule;
  n.S = m.S;
  // The parents of the image (the elements at half their grid points) are for
  // match_neighbourhood's first-step check, which the sqrt3 and sqrt2
  // splits do not take (see there).
  if (!is_primal(split)) return n;
  for (const Index u : n.column_vertex) n.parent.push_back(ring.image_parent[static_cast<std::size_t>(u)]);
  return n;
}

// At a corner the two boundary curves give their tangent eigenvalue twice
// (`curve`: 1/2 for the binary splits, 1/3 for sqrt3's two steps), their
// tangents the left eigenvectors. The basis along the curves: the first
// mask has no weight on the last ring vertex (the second boundary
// neighbour), the second none on the first; each weighs its own boundary
// neighbour 1.
std::optional<std::array<Eigen::VectorXd, 2>> corner_tangent_masks(const Eigen::MatrixXd& S, double curve) {
  const Eigen::Index n = S.rows();
  if (n < 3) return std::nullopt;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(S.transpose() - curve * Eigen::MatrixXd::Identity(n, n));
  lu.setThreshold(1e-10);
  const Eigen::MatrixXd K = lu.kernel();
  if (K.cols() != 2) return std::nullopt;
  Eigen::Matrix2d A;
  A << K(1, 0), K(1, 1), K(n - 1, 0), K(n - 1, 1);
  if (std::fabs(A.determinant()) < 1e-12) return std::nullopt;
  const Eigen::Matrix2d inverse = A.inverse();
  return std::array<Eigen::VectorXd, 2>{K * inverse.col(0), K * inverse.col(1)};
}

// The limit mask with the weights that vanish to rounding made zero, where
// that makes it an exact left eigenvector (l S == l in floating point), as
// e_0 is for an interpolating scheme, whose centre row of S is e_0: the
// eigensolver's vector is e_0 only to rounding (about 1e-16), and the limit
// position is then the vertex itself, exactly. Elsewhere the mask as
// computed.
Eigen::VectorXd exact_zeros(const Eigen::VectorXd& mask, const Eigen::MatrixXd& S) {
  const double largest = mask.cwiseAbs().maxCoeff();
  Eigen::VectorXd snapped = mask;
  for (Eigen::Index a = 0; a < snapped.size(); ++a)
    if (std::fabs(snapped[a]) <= 1e-12 * largest) snapped[a] = 0.0;
  snapped /= snapped.sum();
  const Eigen::RowVectorXd image = snapped.transpose() * S;
  return image == snapped.transpose() ? snapped : mask;
}

bool same(double a, double b) { return std::fabs(a - b) <= 1e-9; }

class MaskCache {
 public:
  MaskCache(const Scheme& scheme, const RefineOptions& rules, BoundaryInterpolation boundary, CreaseMethod method)
      : scheme_(scheme), rules_(rules), boundary_(boundary), method_(method) {
    rules_.start_level = 0;  // the masks' level is even (sqrt3), as the analysis's ring meshes start
    // The ring meshes carry no tags: the mesh's own rules, from its tags
    // where the options leave them open, must reach the analysis.
    rules_.boundary = boundary;
    rules_.crease_method = method;
  }

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
    options.regular_rules = false;  // the masks alone
    options.rules = rules_;
    const ConfigurationAnalysis a = analyze(scheme_, canonical, options);
    Masks masks{a.limit_mask, a.tangent_masks, a.tangent_masks.has_value(), std::nullopt};
    if (masks.limit) masks.limit = exact_zeros(*masks.limit, a.matrix.S);
    if (a.matrix.invariant && a.limit_mask)
      masks.neighbourhood = canonical_neighbourhood(scheme_.split, a.matrix, boundary_, method_);
    if (canonical.kind == Configuration::Kind::corner && a.matrix.invariant) {
      // The curves' pair spans the tangent plane when it is subdominant:
      // lambda_1 = lambda_2 = curve > |lambda_3|: 1/2 per binary step, the
      // analysis step's (arity^-period: 1/3 over sqrt3's two steps).
      const double curve = std::pow(arity(scheme_.split), -scheme_.traits.period);
      masks.tangents = corner_tangent_masks(a.matrix.S, curve);
      const auto& l = a.leading;
      masks.normal = masks.tangents && l.size() >= 4 && same(l[1].real(), curve) && same(l[2].real(), curve) &&
                     same(l[1].imag(), 0.0) && same(l[2].imag(), 0.0) && std::abs(l[3]) < curve - 1e-9;
    }
    return cache_.emplace(key, std::move(masks)).first->second;
  }

 private:
  const Scheme& scheme_;
  RefineOptions rules_;
  BoundaryInterpolation boundary_;
  CreaseMethod method_;
  std::map<std::tuple<int, int, int, double>, Masks> cache_;
};

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
  bool quads;  ///< the split makes quads (quad, sqrt2), else triangles
  /// Primal splits: compare the mesh's own first step with the matrix
  /// (match_neighbourhood). The sqrt3 and sqrt2 splits' matrices span two
  /// steps; their rules read nothing the topology match does not fix.
  bool primal;
  /// One step of the scheme from this level, as stencils (computed on first
  /// use): the match compares its rows with the matrix's.
  struct Step {
    const PolygonMesh& mesh;
    const Scheme& scheme;
    RefineOptions once;
    std::optional<StencilTable> table;
    const StencilTable& rows() {
      if (!table) table = refine_stencil_table(mesh, scheme, once);
      return *table;
    }
  };
  Step& step;
};

// Child vertex numbering of the primal splits: [face points | edge points |
// vertex points] (quad), [edge points | vertex points] (triangle).
Index face_child(const MeshTopology&, Index f) { return f; }
Index edge_child(const MeshTopology& t, Index e, bool quads) { return (quads ? t.face_count() : 0) + e; }
Index vertex_child(const MeshTopology& t, Index v, bool quads) {
  return (quads ? t.face_count() : 0) + t.edge_count() + v;
}

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

// The mesh vertices of the canonical neighbourhood n around v, in the order
// of the matrix's columns: the ring mesh is walked face by face from the
// centre's first face outwards in lockstep with the mesh from v's face at
// `first` (vertex_corners(v)[first], the face whose outgoing edge at v
// plays the first ray), crossing each edge to the face beyond it while that
// face is within the neighbourhood. nullopt where the mesh differs from the
// canonical topology there: another face size, an edge that is a boundary
// (or sharp) in one and not in the other, two canonical vertices on one
// mesh vertex, or an inner vertex (ring < rings: every face around it is in
// the neighbourhood, and the rules of the neighbourhood's image one level
// down read no further) with another valence, vertex rule, a semi-sharp
// tag, or a rule that changes one level down. Edges at inner vertices must
// be smooth or, where the canonical mesh has a boundary, infinitely sharp;
// edges between outer vertices are not read by those rules and may be
// anything. With one ring this is the one-ring match: the faces at v and
// the edges at v.
std::optional<std::vector<Index>> match_neighbourhood(const GenericLevel& g, const Neighbourhood& n, Index v,
                                                      std::size_t first) {
  const MeshTopology& T = n.topology;
  const MeshTopology& t = g.t;
  const auto corners = t.vertex_corners(v);
  std::vector<Index> image(static_cast<std::size_t>(T.vertex_count()), kInvalidIndex);
  std::vector<Index> face_image(static_cast<std::size_t>(T.face_count()), kInvalidIndex);
  std::vector<std::pair<Index, Index>> queue{{n.start, corners[first % corners.size()]}};
  face_image[static_cast<std::size_t>(T.corner_face(n.start))] = t.corner_face(queue.front().second);
  for (std::size_t q = 0; q < queue.size(); ++q) {
    auto [cc, mc] = queue[q];
    const Index size = T.face_size(T.corner_face(cc));
    if (t.face_size(t.corner_face(mc)) != size) return std::nullopt;
    for (Index i = 0; i < size; ++i, cc = T.corner_next(cc), mc = t.corner_next(mc)) {
      Index& w = image[static_cast<std::size_t>(T.corner_vertex(cc))];
      if (w == kInvalidIndex) w = t.corner_vertex(mc);
      else if (w != t.corner_vertex(mc)) return std::nullopt;
      const Index ce = T.corner_edge(cc), me = t.corner_edge(mc);
      const double s = edge_sharpness_of(g.creasing, me);
      const auto sides = T.edge_corners(ce);
      if (sides.size() == 1) {  // the configuration's boundary
        if (s < kInfiniteSharpness) return std::nullopt;
        continue;
      }
      const auto [a, b] = T.edge_vertices(ce);
      if ((n.inner(a) || n.inner(b)) && s != 0.0) return std::nullopt;
      const Index across = sides[0] == cc ? sides[1] : sides[0];
      const Index face = T.corner_face(across);
      if (!n.face_inside[static_cast<std::size_t>(face)]) continue;
      const auto mesh_sides = t.edge_corners(me);
      if (mesh_sides.size() != 2) return std::nullopt;
      const Index mesh_across = mesh_sides[0] == mc ? mesh_sides[1] : mesh_sides[0];
      if (t.corner_vertex(mesh_across) != t.corner_vertex(t.corner_next(mc))) return std::nullopt;  // flipped
      Index& mapped = face_image[static_cast<std::size_t>(face)];
      if (mapped == kInvalidIndex) {
        mapped = t.corner_face(mesh_across);
        queue.emplace_back(across, mesh_across);
      } else if (mapped != t.corner_face(mesh_across)) {
        return std::nullopt;
      }
    }
  }
  std::vector<Index> ring;
  ring.reserve(n.column_vertex.size());
  for (const Index u : n.column_vertex) {
    const Index w = image[static_cast<std::size_t>(u)];
    if (w == kInvalidIndex) return std::nullopt;
    ring.push_back(w);
    if (!n.inner(u)) continue;
    const auto wi = static_cast<std::size_t>(w);
    const VertexRule rule = g.creasing.vertex_rule[wi];
    if (!t.ring_ordered(w) || g.semi_sharp_vertex[wi] || rule != n.rule[static_cast<std::size_t>(u)] ||
        rule != g.creasing.child_vertex_rule[wi])
      return std::nullopt;
    if (T.vertex_kind(u) == VertexKind::interior && t.vertex_face_count(w) != T.vertex_face_count(u))
      return std::nullopt;
  }
  std::vector<std::pair<Index, Index>> column_of;  // (mesh vertex, column), sorted
  for (std::size_t a = 0; a < ring.size(); ++a) column_of.emplace_back(ring[a], static_cast<Index>(a));
  std::sort(column_of.begin(), column_of.end());
  for (std::size_t a = 1; a < column_of.size(); ++a)
    if (column_of[a].first == column_of[a - 1].first) return std::nullopt;
  // The mesh's own first step on the neighbourhood is the matrix: the rules
  // may read more than the topology above checks (the Butterfly rules of an
  // edge read the valence of both ends, ring-r vertices included; the
  // piecewise-smooth rules the sectors of boundary ends). Later steps see
  // the neighbourhood's image, whose vertices of ring > 0 are new (edge and
  // face points, regular), in a region the checks above cover.
  // The sqrt3 and sqrt2 splits' matrices span two steps and their images
  // are not at half the layout, so this check is not made there, and need
  // not be: their rules read a face's corners, a vertex's one-ring and its
  // own valence (interpolatory sqrt3's face rule also its corners'), so an
  // image row of the invariant neighbourhood reads only the matched faces
  // and the inner vertices' valences and rules; they have no sharp
  // features. (Tested: the limits at 2 isolation levels, with extraordinary
  // vertices in every neighbourhood's outer ring, equal those at 3 or 4.)
  if (!g.primal) return ring;
  const StencilTable& rows = g.step.rows();
  Eigen::VectorXd row(static_cast<Eigen::Index>(ring.size()));
  for (std::size_t a = 0; a < ring.size(); ++a) {
    const ImageParent& parent = n.parent[a];
    Index child = kInvalidIndex;
    if (parent.kind == ImageParent::Kind::face) {
      const Index f = face_image[static_cast<std::size_t>(parent.a)];
      if (f == kInvalidIndex) return std::nullopt;
      child = face_child(t, f);
    } else if (parent.kind == ImageParent::Kind::vertex) {
      child = vertex_child(t, image[static_cast<std::size_t>(parent.a)], g.quads);
    } else {
      const Index e = t.find_edge(image[static_cast<std::size_t>(parent.a)], image[static_cast<std::size_t>(parent.b)]);
      if (e == kInvalidIndex) return std::nullopt;
      child = edge_child(t, e, g.quads);
    }
    row.setZero();
    const auto vertices = rows.row_vertices(child);
    const auto weights = rows.row_weights(child);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const auto it = std::lower_bound(column_of.begin(), column_of.end(), std::pair{vertices[i], Index{0}});
      if (it == column_of.end() || it->first != vertices[i]) {
        if (weights[i] != 0.0) return std::nullopt;
        continue;
      }
      row[it->second] += weights[i];
    }
    if ((row.transpose() - n.S.row(static_cast<Eigen::Index>(a))).cwiseAbs().maxCoeff() > 1e-12) return std::nullopt;
  }
  return ring;
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
  // Semi-sharp features at v change its rule on a later level.
  bool settled = rule == g.creasing.child_vertex_rule[vi] && !g.semi_sharp_vertex[vi];
  int sharp = 0;
  for (const Index e : t.vertex_edges(v)) {
    const double s = edge_sharpness_of(g.creasing, e);
    if (s >= kInfiniteSharpness) ++sharp;
    else if (s > 0.0) settled = false;
  }
  bool canonical = t.ring_ordered(v) && settled;
  const Index face_size = g.quads ? 4 : 3;
  for (const Index c : t.vertex_corners(v)) canonical = canonical && t.face_size(t.corner_face(c)) == face_size;
  const VertexKind kind = t.vertex_kind(v);
  if (rule == VertexRule::corner) {
    // Every rule here keeps an infinitely sharp corner, but not one whose
    // sharpness decays (semi-sharp edges or vertex sharpness): it moves once
    // its rule changes. Its tangents: the
    // corner configuration's pair 1/2 on one sector (a boundary corner's
    // only one, an interior corner's first), the sector angle as the rules
    // give it.
    // The flatness modification applies at boundary corners of one sector
    // only: a concave sector beside others matches no configuration.
    if (!settled) return std::nullopt;
    GenericLimit corner{p, std::nullopt, std::nullopt};
    if (!canonical || sharp < 2 || (kind != VertexKind::boundary && kind != VertexKind::interior)) return corner;
    const Sector sector = sharp_sectors(g, v).front();
    Configuration c{Configuration::Kind::corner, static_cast<int>(sector.count), CornerType::convex, 0.0};
    if (!g.sector_angle.empty()) c.angle = g.sector_angle[vi];
    if (c.angle > std::numbers::pi) c.corner = CornerType::concave;
    if (c.corner == CornerType::concave && !(kind == VertexKind::boundary && sharp == 2)) return corner;
    const Masks& m = cache.at(c);
    if (!m.limit || !m.tangents || !m.neighbourhood) return corner;
    const auto ring = match_neighbourhood(g, *m.neighbourhood, v, sector.first);
    if (!ring) return corner;
    GenericLimit result = from_masks(g, v, m, *ring, sector);
    result.position = p;
    return result;
  }
  const bool smooth_interior = kind == VertexKind::interior && rule == VertexRule::smooth && sharp == 0;
  const bool smooth_boundary = kind == VertexKind::boundary && rule == VertexRule::crease && sharp == 2 &&
                               t.vertex_face_count(v) >= 1;
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
      if (!m.limit || !m.neighbourhood) return std::nullopt;
      // The position reads the curve only (the canonical boundary: the
      // centre and the rays' vertices).
      const Eigen::VectorXd& mask = *m.limit;
      const Neighbourhood& n = *m.neighbourhood;
      double off_curve = 0.0;
      for (Eigen::Index a = 0; a < mask.size(); ++a)
        if (n.topology.vertex_kind(n.column_vertex[static_cast<std::size_t>(a)]) != VertexKind::boundary)
          off_curve += std::fabs(mask[a]);
      if (off_curve > 1e-12) return std::nullopt;
      const auto ring = match_neighbourhood(g, n, v, sector.first);
      if (!ring) return std::nullopt;
      return from_masks(g, v, m, *ring, sector);
    }
    return std::nullopt;
  }
  const int k = smooth_interior ? t.valence(v) : t.vertex_face_count(v);
  // Interior k = 2 is the quad split's only (valence_two_ring_mesh): two
  // triangles around an interior vertex share all three edges (the one
  // opposite it is non-manifold, or the two are a closed component), and
  // the sqrt3 and sqrt2 splits' two-step matrices need a linear layout.
  if (smooth_interior && k == 2 && !(g.quads && g.primal)) return std::nullopt;
  const Masks& m = cache.at({smooth_interior ? Configuration::Kind::interior : Configuration::Kind::boundary, k});
  const Sector all{0, t.vertex_corners(v).size()};
  if (!m.limit || !m.neighbourhood) return std::nullopt;
  const auto ring = match_neighbourhood(g, *m.neighbourhood, v, all.first);
  if (!ring) return std::nullopt;
  return from_masks(g, v, m, *ring, all);
}

// Whether a semi-sharp edge or vertex sharpness is at v or a neighbour of
// it: a rule there changes on a later level.
bool near_semi_sharp(const GenericLevel& g, Index v) {
  const auto semi_sharp_at = [&](Index w) {
    if (g.semi_sharp_vertex[static_cast<std::size_t>(w)]) return true;
    for (const Index e : g.t.vertex_edges(w)) {
      const double s = edge_sharpness_of(g.creasing, e);
      if (s > 0.0 && s < kInfiniteSharpness) return true;
    }
    return false;
  };
  if (semi_sharp_at(v)) return true;
  for (const Index e : g.t.vertex_edges(v))
    if (semi_sharp_at(g.t.other_vertex(e, v))) return true;
  return false;
}

// Refinement steps after which the closed forms apply everywhere they can:
// one where a face has another size than the split's, ceil(s) for the
// largest finite sharpness s; at most `cap` (the caller also stops before a
// level over its face budget).
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

// The face and corner counts of a whole level, which a cut level no longer
// has: the primal splits' children follow from them.
struct WholeLevel {
  std::int64_t faces = 0, corners = 0;
  WholeLevel child(SplitRule split) const {
    // Quad split: a quad per corner; triangle split: four triangles a face.
    if (split == SplitRule::quad) return {corners, 4 * corners};
    return {4 * faces, 12 * faces};
  }
};

}  // namespace

std::optional<std::string> limit_unavailable(const Scheme& scheme) {
  if (scheme.split == SplitRule::quasi_4_8)
    return "no limit positions for quasi 4-8: its bisection follows the geometry, so its steps are not stationary and "
           "no fixed subdivision matrix gives masks (the analysis's matrices belong to its planar n-gon experiment)";
  // Composite schemes take the route of their split, as any scheme: the
  // analysis's masks of a whole level (gcc and midpoint of odd degree,
  // composite:Tvv4,... and composite:Tvv3,..., whose averages read only
  // topology and valences, which the neighbourhood match fixes), or the dual
  // route (gcc and midpoint of even degree), whose neighbourhood walk reads
  // as many rings as the analysis's matrix spans.
  const bool point_split = scheme.split == SplitRule::sqrt3 || scheme.split == SplitRule::sqrt2;
  if (!is_primal(scheme.split) && !point_split && scheme.split != SplitRule::dual && scheme.split != SplitRule::midedge)
    return std::string("no limit positions for the ") + to_string(scheme.split) +
           ": they are written for the primal, sqrt3, sqrt2, dual and midedge splits";
  return std::nullopt;
}

LimitResult limit_positions(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& options) {
  if (options.isolation_levels < 0 || options.max_resolve_levels < 0 || options.max_resolve_faces < 0)
    throw InvalidInputError("limit: refinement levels and faces must be >= 0");
  if (const auto reason = limit_unavailable(scheme)) throw InvalidInputError(std::string(scheme.name) + ": " + *reason);
  if (scheme.split == SplitRule::dual || scheme.split == SplitRule::midedge)
    return dual_limit_positions(mesh, scheme, options);
  const bool point_split = scheme.split == SplitRule::sqrt3 || scheme.split == SplitRule::sqrt2;
  // The closed forms are those of the standard rules. Under the
  // piecewise-smooth rules the generic masks of the modified matrices apply,
  // after at least one step: a vertex next to an extraordinary sharp vertex
  // has a modified edge point in its ring, which its configuration's matrix
  // does not describe; its vertex point one level down has none.
  const bool piecewise = options.refine.boundary_rules == BoundaryRules::piecewise_smooth;
  const bool closed_form = options.route == LimitRoute::closed_form && scheme.limit_masks != nullptr && !piecewise;
  int levels = closed_form ? levels_to_resolve(mesh, scheme, options.max_resolve_levels)
               : piecewise ? std::max(1, options.isolation_levels)
                           : options.isolation_levels;
  // Arity sqrt 2: two steps make a binary level, and the isolation counts
  // those (extraordinary vertices as far apart as after binary levels).
  if (scheme.split == SplitRule::sqrt2) levels *= 2;
  // The analysis's two-step sqrt3 matrix starts with a step that does not
  // trisect the boundary: so must the masks' level, counted from level 0
  // (a mesh at an odd start level takes an odd number of steps).
  if (scheme.split == SplitRule::sqrt3) levels += (options.refine.start_level + levels) % 2;
  RefineOptions check = options.refine;
  check.levels = levels;
  check_refinable(mesh, scheme, check);

  // Each input vertex is followed through the levels by each split's own
  // map (its vertex point), refining one level at a time on a hierarchy that
  // keeps its finest level; the hierarchy carries the level number, so
  // sqrt3's boundary steps alternate as in one run.
  std::vector<Index> where(static_cast<std::size_t>(mesh.vertex_count()));
  std::iota(where.begin(), where.end(), 0);
  Hierarchy hierarchy{{{mesh, options.refine.start_level, std::nullopt}}};
  RefineOptions one = options.refine;
  one.levels = 1;
  // The closed forms need only the followed vertices' surroundings: each
  // level is cut down to them (analysis/local_refinement.h), and the face
  // budget counts the whole level's faces.
  const bool crop = options.local_levels && closed_form && is_primal(scheme.split) && !scheme.traits.needs_closed_mesh;
  WholeLevel whole{hierarchy.finest().mesh.face_count(), hierarchy.finest().mesh.corner_count()};
  for (int l = 0; l < levels; ++l) {
    // The closed-form route stops before a level over its face budget.
    const WholeLevel child = whole.child(scheme.split);
    if (closed_form && !point_split && child.faces > options.max_resolve_faces) {
      levels = l;
      break;
    }
    refine_further(hierarchy, scheme, 1, one, KeepLevels::last);
    const SplitMap& map = *hierarchy.finest().map;
    for (Index& w : where) w = map.vertex_point(w);
    if (crop) {
      PolygonMesh& level = hierarchy.levels.back().mesh;
      level = detail::crop_around(level, where, detail::kCropRings);
      // The cut leaves vertices with separate fans, which refinement treats
      // as sharp: only outside the rings kept exact.
      one.allow_non_manifold = true;
      whole = child;
    } else {
      whole = {hierarchy.finest().mesh.face_count(), hierarchy.finest().mesh.corner_count()};
    }
  }
  PolygonMesh current = std::move(hierarchy.levels.back().mesh);

  const MeshTopology t(current);
  const BoundaryInterpolation boundary = boundary_of(current, options.refine);
  const CreaseMethod method = crease_method_of(current, options.refine);
  const LevelCreasing creasing = compute_creasing(current, t, boundary, method);
  std::vector<char> semi_sharp_vertex(static_cast<std::size_t>(current.vertex_count()), 0);
  for (const CornerTag& c : current.tags.corners)
    if (c.sharpness > 0.0 && c.sharpness < kInfiniteSharpness) semi_sharp_vertex[static_cast<std::size_t>(c.vertex)] = 1;
  const detail::LimitLevel level{t, creasing, current.positions, semi_sharp_vertex};
  const bool quads = scheme.split == SplitRule::quad || scheme.split == SplitRule::sqrt2;
  const std::vector<double> sector_angle =
      piecewise ? detail::sector_angles(current, t, creasing) : std::vector<double>{};
  RefineOptions step_options = one;
  step_options.on_level = nullptr;
  GenericLevel::Step step{current, scheme, step_options, std::nullopt};
  const GenericLevel generic{t, creasing, current.positions, semi_sharp_vertex, sector_angle, quads, !point_split,
                             step};
  MaskCache cache(scheme, options.refine, boundary, method);
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
        result.sources[i] = limit->eigenvectors ? LimitSource::generic : LimitSource::closed_form;
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
    if (near_semi_sharp(generic, v)) ++result.semi_sharp;
  }
  for (const CreaseTag& c : current.tags.creases)
    if (c.sharpness < kInfiniteSharpness) result.sharpness_left = std::max(result.sharpness_left, c.sharpness);
  for (const CornerTag& c : current.tags.corners)
    if (c.sharpness < kInfiniteSharpness) result.sharpness_left = std::max(result.sharpness_left, c.sharpness);
  return result;
}

}  // namespace subdiv
