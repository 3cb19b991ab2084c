#include "analysis/extraordinary_patch.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <string>

#include "analysis/dart_limit.h"
#include "analysis/patch_basis.h"
#include "analysis/patch_points.h"
#include "subdiv/core/error.h"
#include "subdiv/core/stencil_table.h"
#include "subdiv/refine/configuration.h"
#include "subdiv/refine/refine.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "subdiv/topology/split.h"

namespace subdiv {

std::optional<FaceRing> face_ring(const MeshTopology& topology, Index corner, const LevelCreasing* creasing) {
  FaceRing ring;
  // Rings are a few dozen vertices: a linear search keeps the walk's cost
  // independent of the mesh's size.
  const auto visit_face = [&](Index from) {
    const Index face = topology.corner_face(from);
    ring.signature.push_back(static_cast<int>(topology.face_size(face)));
    Index c = from;
    do {
      const Index v = topology.corner_vertex(c);
      auto at = std::find(ring.vertices.begin(), ring.vertices.end(), v);
      if (at == ring.vertices.end()) at = ring.vertices.insert(at, v);
      ring.signature.push_back(static_cast<int>(at - ring.vertices.begin()));
      c = topology.corner_next(c);
    } while (c != from);
  };
  Index c = corner;
  do {
    const Index v = topology.corner_vertex(c);
    if (topology.fan_count(v) != 1) return std::nullopt;
    bool sharp = topology.vertex_kind(v) != VertexKind::interior;
    if (creasing) {
      for (const Index e : topology.vertex_edges(v)) sharp |= edge_sharpness_of(*creasing, e) > 0.0;
    }
    Index around = c;
    int faces = 0;
    if (!sharp) {
      // Counter-clockwise around v from the face: across the edge that
      // enters v in each face.
      do {
        visit_face(around);
        around = topology.corner_across(topology.corner_prev(around));
        if (around == kInvalidIndex || ++faces > topology.vertex_face_count(v)) return std::nullopt;
      } while (around != c);
    } else {
      if (!creasing) return std::nullopt;
      // The face's sector between sharp edges, from its first face; the
      // signature notes v's rule and how far into the sector the face lies.
      const auto sector = sector_corners(topology, *creasing, c);
      if (!sector) return std::nullopt;
      ring.signature.push_back(-10 - static_cast<int>(creasing->vertex_rule[static_cast<std::size_t>(v)]));
      ring.signature.push_back(-100 - static_cast<int>(std::find(sector->begin(), sector->end(), c) - sector->begin()));
      for (const Index k : *sector) visit_face(k);
    }
    ring.signature.push_back(-1);  // end of the fan
    c = topology.corner_next(c);
  } while (c != corner);
  return ring;
}

namespace {

[[noreturn]] void inconsistent(int valence, const std::string& what) {
  throw std::logic_error("extraordinary patch, valence " + std::to_string(valence) + ": " + what);
}

/// The combinations `rows` of `table`'s rows as a dense matrix over the
/// ring's columns.
Eigen::MatrixXd rows_over_ring(const StencilTable& table, const std::vector<PatchStencil>& rows,
                               const std::vector<int>& column_of, int columns, int valence) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), columns);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (int i = 0; i < rows[r].size; ++i) {
      const Index row = rows[r].vertex[static_cast<std::size_t>(i)];
      const double w = rows[r].weight[static_cast<std::size_t>(i)];
      const auto vertices = table.row_vertices(row);
      const auto weights = table.row_weights(row);
      for (std::size_t e = 0; e < vertices.size(); ++e) {
        const int column = column_of[static_cast<std::size_t>(vertices[e])];
        if (column < 0) inconsistent(valence, "a child row reads a vertex outside the face ring");
        m(static_cast<Eigen::Index>(r), column) += w * weights[e];
      }
    }
  }
  return m;
}

/// The parent's infinitely sharp crease and corner tags on the child of a
/// split: each crease on its edge's two children.
void carry_tags(const PolygonMesh& parent, const MeshTopology& topology, const SplitMap& map, PolygonMesh& child) {
  for (const CreaseTag& tag : parent.tags.creases) {
    const Index e = topology.find_edge(tag.v0, tag.v1);
    if (e == kInvalidIndex) continue;
    child.tags.creases.push_back({map.vertex_point(tag.v0), map.edge_point(e), tag.sharpness});
    child.tags.creases.push_back({map.edge_point(e), map.vertex_point(tag.v1), tag.sharpness});
  }
  for (const CornerTag& tag : parent.tags.corners) {
    CornerTag child_tag = tag;
    child_tag.vertex = map.vertex_point(tag.vertex);
    child.tags.corners.push_back(child_tag);
  }
}

/// Plain rows: each a vertex of weight 1.
std::vector<PatchStencil> plain_rows(std::span<const Index> vertices) {
  std::vector<PatchStencil> rows(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    rows[i].vertex[0] = vertices[i];
    rows[i].weight[0] = 1.0;
    rows[i].size = 1;
  }
  return rows;
}

/// A regular child's frame in F's parameters: its origin and its axes'
/// steps (the child's u runs along s, its v along t).
struct ChildFrame {
  std::array<double, 2> origin;
  std::array<double, 2> axis;
};
// Quad split: the children at (1/2, 0), (1/2, 1/2) and (0, 1/2).
constexpr std::array<ChildFrame, 3> kQuadChildren = {{{{0.5, 0.0}, {0.5, 0.5}}, {{0.5, 0.5}, {0.5, 0.5}},
                                                      {{0.0, 0.5}, {0.5, 0.5}}}};
// Triangle split: the children at the corners (1, 0) and (0, 1), and the
// middle one, turned a half turn.
constexpr std::array<ChildFrame, 3> kTriangleChildren = {{{{0.5, 0.0}, {0.5, 0.5}}, {{0.0, 0.5}, {0.5, 0.5}},
                                                          {{0.5, 0.5}, {-0.5, -0.5}}}};

}  // namespace

ExtraordinaryPatch::ExtraordinaryPatch(SplitRule split, int valence)
    : ExtraordinaryPatch(split, Configuration{Configuration::Kind::interior, valence}, 0) {}

ExtraordinaryPatch::ExtraordinaryPatch(SplitRule split, const Configuration& configuration, int position, bool dart,
                                       const Scheme* scheme)
    : split_(split), valence_(configuration.k), configuration_(configuration), position_(position), dart_(dart) {
  if (split != SplitRule::quad && split != SplitRule::triangle) {
    throw InvalidInputError("extraordinary patch: only the quad and triangle splits have one");
  }
  const bool interior = configuration.kind == Configuration::Kind::interior;
  const int valence = configuration.k;
  if (interior && valence < 3)
    throw InvalidInputError("extraordinary patch: valence " + std::to_string(valence) + " is below 3");
  if ((!interior || dart) && (valence < 1 || position < 0 || position >= valence))
    throw InvalidInputError("extraordinary patch: " + configuration.name() + " has no face " + std::to_string(position));
  if (dart && !interior) throw InvalidInputError("extraordinary patch: a dart is an interior configuration");
  const bool quads = split == SplitRule::quad;
  // Four rings keep the ring mesh's own boundary away from every row read.
  // Its boundary edges are sharp, and a boundary centre keeps the crease
  // rule whatever its face count (edge_only), unless it is a corner.
  RingMesh model = ring_mesh(split, configuration, 4);
  if (dart) detail::add_dart(model, quads ? 4 : 6);
  const MeshTopology parent(model.mesh);
  const auto creasing_of = [](const PolygonMesh& mesh, const MeshTopology& topology) {
    return compute_creasing(mesh, topology, BoundaryInterpolation::edge_only, CreaseMethod::uniform);
  };
  const LevelCreasing parent_creasing = creasing_of(model.mesh, parent);
  // F: the face `position` steps counter-clockwise from the sector's first
  // (its edge leaving the centre is the boundary); any face of an interior
  // vertex.
  // (A dart's crease leaves the centre along the first face's edge.)
  Index corner = parent.vertex_corners(model.centre)[0];
  if (!interior || dart) {
    if (!interior)
      for (const Index c : parent.vertex_corners(model.centre))
        if (parent.corner_across(c) == kInvalidIndex) corner = c;
    for (int i = 0; i < position; ++i) corner = parent.corner_across(parent.corner_prev(corner));
  }
  const std::optional<FaceRing> ring = face_ring(parent, corner, &parent_creasing);
  if (!ring || (interior && !dart && ring->vertices.size() != static_cast<std::size_t>(quads ? 2 * valence + 8 : valence + 6))) {
    inconsistent(valence, "the model face's ring has another size than 2N + 8 (quads) or N + 6 (triangles)");
  }
  signature_ = ring->signature;
  for (const Index v : ring->vertices) layout_.push_back(model.mesh.positions[static_cast<std::size_t>(v)]);
  const int size = static_cast<int>(ring->vertices.size());
  std::vector<int> column_of(static_cast<std::size_t>(parent.vertex_count()), -1);
  for (int i = 0; i < size; ++i) column_of[static_cast<std::size_t>(ring->vertices[static_cast<std::size_t>(i)])] = i;

  RefineOptions one_step;
  one_step.levels = 1;
  one_step.regular_grids = false;
  one_step.boundary = BoundaryInterpolation::edge_only;
  const Scheme& rules = scheme ? *scheme : quads ? catmull_clark_scheme() : loop_scheme();
  if (rules.split != split) throw InvalidInputError("extraordinary patch: " + std::string(rules.name) + " has another split");
  const StencilTable table = refine_stencil_table(model.mesh, rules, one_step);
  PolygonMesh child_mesh;
  const SplitMap map = split_topology(model.mesh, parent, split, child_mesh);
  carry_tags(model.mesh, parent, map, child_mesh);
  const MeshTopology child(child_mesh);
  const LevelCreasing child_creasing = creasing_of(child_mesh, child);

  // The parameter of each child vertex of F in F's frame.
  constexpr std::array<std::array<double, 2>, 4> kQuadCorner = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  constexpr std::array<std::array<double, 2>, 4> kTriangleCorner = {{{0, 0}, {1, 0}, {0, 1}, {0, 0}}};
  const auto& corner_parameter = quads ? kQuadCorner : kTriangleCorner;
  const std::size_t corners = quads ? 4 : 3;
  std::vector<std::array<double, 2>> parameter(static_cast<std::size_t>(child.vertex_count()), {-1.0, -1.0});
  Index c = corner;
  for (std::size_t k = 0; k < corners; ++k, c = parent.corner_next(c)) {
    const auto& [s, t] = corner_parameter[k];
    const auto& [ns, nt] = corner_parameter[(k + 1) % corners];
    parameter[static_cast<std::size_t>(map.vertex_point(parent.corner_vertex(c)))] = {s, t};
    parameter[static_cast<std::size_t>(map.edge_point(parent.corner_edge(c)))] = {(s + ns) / 2, (t + nt) / 2};
  }
  if (quads) parameter[static_cast<std::size_t>(map.face_point(parent.corner_face(corner)))] = {0.5, 0.5};
  // The corner of a child of F at parameter `frame.origin` whose next corner
  // lies along the frame's u axis.
  // The corner of a face among `faces` of `mesh` at parameter
  // `frame.origin` whose next corner lies along the frame's u axis.
  const auto corner_at = [&](const MeshTopology& mesh, const std::vector<std::array<double, 2>>& at,
                             std::pair<Index, Index> faces, const ChildFrame& frame) {
    for (Index f = faces.first; f < faces.second; ++f) {
      for (Index k = 0; k < mesh.face_size(f); ++k) {
        const Index cc = mesh.face_first_corner(f) + k;
        const auto& p = at[static_cast<std::size_t>(mesh.corner_vertex(cc))];
        const auto& q = at[static_cast<std::size_t>(mesh.corner_vertex(mesh.corner_next(cc)))];
        if (p == frame.origin && q[0] == frame.origin[0] + frame.axis[0] && q[1] == frame.origin[1]) return cc;
      }
    }
    inconsistent(valence_, "no child face has the expected frame");
  };
  const auto children_of_F = child_faces(parent, split, parent.corner_face(corner));
  const Index centre_child = corner_at(child, parameter, children_of_F, {{0.0, 0.0}, {0.5, 0.5}});
  const std::optional<FaceRing> child_ring = face_ring(child, centre_child, &child_creasing);
  if (!child_ring || child_ring->signature != signature_) inconsistent(valence_, "the centre child's ring differs");
  A_ = rows_over_ring(table, plain_rows(child_ring->vertices), column_of, size, valence_);
  // A regular piece: the patch points at `origin` of `mesh`, as rows of
  // `stencils` over the ring.
  // (false where the child is no regular patch, if `may_fail`).
  const auto piece = [&](const MeshTopology& mesh, const LevelCreasing& creasing, const StencilTable& stencils,
                         Index origin, const ChildFrame& frame, bool may_fail = false) {
    std::vector<PatchStencil> rows;
    if (quads) {
      const auto points = bicubic_patch_stencils(mesh, creasing, origin);
      if (points) rows.assign(points->begin(), points->end());
    } else {
      const auto points = box_spline_patch_stencils(mesh, creasing, origin);
      if (points) rows.assign(points->begin(), points->end());
    }
    if (rows.empty()) {
      if (may_fail) return false;
      inconsistent(valence_, "a regular piece has no regular patch");
    }
    children_.push_back({rows_over_ring(stencils, rows, column_of, size, valence_), frame.origin, frame.axis});
    return true;
  };
  const auto& frames = quads ? kQuadChildren : kTriangleChildren;
  for (std::size_t k = 0; k < 2; ++k)
    piece(child, child_creasing, table, corner_at(child, parameter, children_of_F, frames[k]), frames[k]);
  const bool middle_split =
      !piece(child, child_creasing, table, corner_at(child, parameter, children_of_F, frames[2]), frames[2], !quads);
  if (middle_split) {
    // The triangle split's middle child is no regular patch at Loop's
    // valence 3 (the triangles around its corners wrap around the corner:
    // its patch points are not distinct) and in a sector of one face (it
    // touches both sharp edges): its four children, one level further
    // down, are the pieces instead.
    RefineOptions two_steps = one_step;
    two_steps.levels = 2;
    const StencilTable table2 = refine_stencil_table(model.mesh, rules, two_steps);
    PolygonMesh grandchild_mesh;
    const SplitMap map2 = split_topology(child_mesh, child, split, grandchild_mesh);
    carry_tags(child_mesh, child, map2, grandchild_mesh);
    const MeshTopology grandchild(grandchild_mesh);
    const LevelCreasing grandchild_creasing = creasing_of(grandchild_mesh, grandchild);
    // Level-2 parameters: vertex points keep theirs, edge points of edges
    // inside F take their ends' midpoint.
    std::vector<std::array<double, 2>> parameter2(static_cast<std::size_t>(grandchild.vertex_count()), {-1.0, -1.0});
    for (Index v = 0; v < child.vertex_count(); ++v)
      parameter2[static_cast<std::size_t>(map2.vertex_point(v))] = parameter[static_cast<std::size_t>(v)];
    for (Index e = 0; e < child.edge_count(); ++e) {
      const auto [a, b] = child.edge_vertices(e);
      const auto& pa = parameter[static_cast<std::size_t>(a)];
      const auto& pb = parameter[static_cast<std::size_t>(b)];
      if (pa[0] >= 0.0 && pb[0] >= 0.0)
        parameter2[static_cast<std::size_t>(map2.edge_point(e))] = {(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2};
    }
    const ChildFrame& middle = frames[2];
    const Index middle_face = child.corner_face(corner_at(child, parameter, children_of_F, middle));
    constexpr std::array<ChildFrame, 4> kSubFrames = {{{{0.0, 0.0}, {0.5, 0.5}}, kTriangleChildren[0],
                                                       kTriangleChildren[1], kTriangleChildren[2]}};
    for (const ChildFrame& sub : kSubFrames) {
      const ChildFrame frame{{middle.origin[0] + sub.origin[0] * middle.axis[0], middle.origin[1] + sub.origin[1] * middle.axis[1]},
                             {sub.axis[0] * middle.axis[0], sub.axis[1] * middle.axis[1]}};
      piece(grandchild, grandchild_creasing, table2,
            corner_at(grandchild, parameter2, child_faces(child, split, middle_face), frame), frame);
    }
  }
  // The corner's limit: row 0 (the centre) of A^256, by repeated squaring;
  // the subdominant eigenvalues' 256th powers are below 1e-40.
  Eigen::MatrixXd power = A_;
  for (int i = 0; i < 8; ++i) power = power * power;
  limit_row_ = power.row(0).transpose();

  // The cached rows: A_k A^n for the first kCachedLevels levels, then
  // A_k A^n (I - 1 l) (the ring moved onto its limit l first, by products
  // from I - 1 l, so that rows of decaying size keep their digits).
  power = Eigen::MatrixXd::Identity(size, size);  // A^n
  for (int n = 0; n < kCachedLevels; ++n, power = A_ * power)
    for (const Child& regular : children_) level_rows_.emplace_back(regular.rows * power);
  step_ = power;
  Eigen::MatrixXd moved = Eigen::MatrixXd::Identity(size, size) -
                          Eigen::VectorXd::Ones(size) * limit_row_.transpose();  // A^n (I - 1 l)
  for (int n = 0; n < kCachedLevels; ++n) moved = A_ * moved;
  for (int n = kCachedLevels; n < 2 * kCachedLevels; ++n, moved = A_ * moved)
    for (const Child& regular : children_) level_rows_.emplace_back(regular.rows * moved);

  // The eigenbasis, kept where it reproduces A to working accuracy.
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(A_);
  if (solver.info() == Eigen::Success) {
    const Eigen::MatrixXcd V = solver.eigenvectors();
    const Eigen::FullPivLU<Eigen::MatrixXcd> lu(V);
    if (lu.isInvertible()) {
      const Eigen::MatrixXcd V_inverse = lu.inverse();
      const Eigen::MatrixXcd rebuilt = V * solver.eigenvalues().asDiagonal() * V_inverse;
      if ((rebuilt - A_.cast<std::complex<double>>()).cwiseAbs().maxCoeff() < 1e-12) {
        eigenbasis_ = true;
        eigenvalues_ = solver.eigenvalues();
        V_inverse_ = V_inverse;
        for (const Child& regular : children_) child_V_.push_back(regular.rows.cast<std::complex<double>>() * V);
      }
    }
  }
}

std::size_t ExtraordinaryPatch::child_holding(double s, double t) const noexcept {
  if (split_ == SplitRule::quad) return s >= 0.5 ? (t >= 0.5 ? 1 : 0) : 2;
  if (s >= 0.5) return 0;
  if (t >= 0.5) return 1;
  if (children_.size() == 3) return 2;
  // The middle child's four pieces: the one (s, t) lies in, or nearest.
  std::size_t best = 2;
  double best_outside = std::numeric_limits<double>::infinity();
  for (std::size_t k = 2; k < children_.size(); ++k) {
    const Child& c = children_[k];
    const double u = (s - c.origin[0]) / c.axis[0], v = (t - c.origin[1]) / c.axis[1];
    const double outside = std::max({0.0, -u, -v, u + v - 1.0});
    if (outside < best_outside) {
      best = k;
      best_outside = outside;
    }
  }
  return best;
}

void ExtraordinaryPatch::check(std::span<const Vec3> ring, double s, double t) const {
  if (static_cast<Eigen::Index>(ring.size()) != A_.rows()) {
    throw InvalidInputError("extraordinary patch: " + std::to_string(ring.size()) + " control points for a ring of " +
                            std::to_string(A_.rows()));
  }
  // Written so that NaN fails too.
  if (!(s >= 0.0 && t >= 0.0 && (split_ == SplitRule::quad ? std::max(s, t) : s + t) <= 1.0)) {
    throw InvalidInputError("extraordinary patch: (" + std::to_string(s) + ", " + std::to_string(t) +
                            ") is outside the face");
  }
}

ExtraordinaryPatch::Location ExtraordinaryPatch::locate(double s, double t) const noexcept {
  // Level n: the deepest centre child that holds (s, t) outside its own
  // centre child; doubling is exact in floating point.
  const bool quads = split_ == SplitRule::quad;
  Location at;
  while ((quads ? std::max(s, t) : s + t) < 0.5) {
    s *= 2.0;
    t *= 2.0;
    ++at.level;
  }
  at.child = child_holding(s, t);
  const Child& child = children_[at.child];
  at.u = (s - child.origin[0]) / child.axis[0];
  at.v = (t - child.origin[1]) / child.axis[1];
  return at;
}

Vec3 ExtraordinaryPatch::corner_limit(std::span<const Vec3> ring) const noexcept {
  Vec3 limit{};
  for (std::size_t i = 0; i < ring.size(); ++i) limit += limit_row_(static_cast<Eigen::Index>(i)) * ring[i];
  return limit;
}

PatchPoint ExtraordinaryPatch::to_face(PatchPoint p, std::size_t child) const noexcept {
  // The child frame's chain factors (1 / axis steps) on the derivatives.
  const double cu = 1.0 / children_[child].axis[0], cv = 1.0 / children_[child].axis[1];
  p.du = cu * p.du;
  p.dv = cv * p.dv;
  p.duu = (cu * cu) * p.duu;
  p.duv = (cu * cv) * p.duv;
  p.dvv = (cv * cv) * p.dvv;
  return p;
}

PatchPoint ExtraordinaryPatch::evaluate(std::span<const Vec3> ring, double s, double t) const {
  check(ring, s, t);
  if (s == 0.0 && t == 0.0) return {corner_limit(ring), {}, {}, {}, {}, {}};
  Location at = locate(s, t);
  if (at.level < 2 * kCachedLevels) return to_face(evaluate_cached(ring, at), at.child);
  // Closer than 2^-(2 kCachedLevels): the eigenbasis, whose scaling keeps
  // every derivative exact however close to the corner.
  if (eigenbasis_) return evaluate_in_eigenbasis(ring, s, t);
  // Where A has none, steps of kCachedLevels levels: the ring moved so that
  // the corner's limit is the origin,
  // times A^kCachedLevels, scaled by 2^kCachedLevels (the first
  // derivatives' growth; positions are scaled back below, second
  // derivatives get one more factor); then the cached levels. Each step is
  // moved back onto its limit: the constant component's rounding, left in,
  // would grow by the scale every step while the rest does not.
  thread_local std::vector<Vec3> moved, stepped;
  moved.assign(ring.begin(), ring.end());
  stepped.resize(ring.size());
  Vec3 limit{};  // the corner's limit: the moves, each scaled back
  const auto recentre = [&](int shift) {
    const Vec3 centre = corner_limit(moved);
    for (Vec3& p : moved) p = p - centre;
    limit += Vec3{std::ldexp(centre.x, -shift), std::ldexp(centre.y, -shift), std::ldexp(centre.z, -shift)};
  };
  recentre(0);
  const double growth = std::ldexp(1.0, kCachedLevels);
  int shift = 0;
  for (; at.level >= kCachedLevels; at.level -= kCachedLevels) {
    for (std::size_t r = 0; r < ring.size(); ++r) {
      const double* row = step_.data() + r * ring.size();
      Vec3 p{};
      for (std::size_t i = 0; i < ring.size(); ++i) p += row[i] * moved[i];
      stepped[r] = growth * p;
    }
    moved.swap(stepped);
    shift += kCachedLevels;
    recentre(shift);
  }
  PatchPoint p = evaluate_cached(moved, at);
  // ldexp: 2^-n and 2^n apart can leave the double range where the results
  // do not.
  const auto scaled = [](Vec3 v, int e) { return Vec3{std::ldexp(v.x, e), std::ldexp(v.y, e), std::ldexp(v.z, e)}; };
  p.position = limit + scaled(p.position, -shift);
  p.duu = scaled(p.duu, shift);
  p.duv = scaled(p.duv, shift);
  p.dvv = scaled(p.dvv, shift);
  return to_face(p, at.child);
}

PatchPoint ExtraordinaryPatch::evaluate_cached(std::span<const Vec3> ring, const Location& at) const {
  // The child's regular patch points, A_k A^n times the ring (from level
  // kCachedLevels on, the ring moved onto its limit, added back below);
  // then its derivatives in F's level-n frame, 2^n per order.
  const auto& rows = level_rows_[children_.size() * static_cast<std::size_t>(at.level) + at.child];
  const auto patch_points = [&](auto& points) {
    for (std::size_t r = 0; r < points.size(); ++r) {
      const double* row = rows.data() + r * ring.size();
      Vec3 p{};
      for (std::size_t i = 0; i < ring.size(); ++i) p += row[i] * ring[i];
      points[r] = p;
    }
  };
  PatchPoint point;
  if (split_ == SplitRule::quad) {
    std::array<Vec3, 16> points;
    patch_points(points);
    point = bicubic_bspline_point([&](std::size_t i) { return points[i]; }, at.u, at.v);
  } else {
    std::array<Vec3, 12> points;
    patch_points(points);
    point = box_spline_point(points, at.u, at.v);
  }
  if (at.level >= kCachedLevels) point.position += corner_limit(ring);
  const double first = std::ldexp(1.0, at.level), second = first * first;
  point.du = first * point.du;
  point.dv = first * point.dv;
  point.duu = second * point.duu;
  point.duv = second * point.duv;
  point.dvv = second * point.dvv;
  return point;
}

PatchPoint ExtraordinaryPatch::evaluate_in_eigenbasis(std::span<const Vec3> ring, double s, double t) const {
  check(ring, s, t);
  if (s == 0.0 && t == 0.0) return {corner_limit(ring), {}, {}, {}, {}, {}};
  const Location at = locate(s, t);
  const int level = at.level;
  const std::size_t k = at.child;
  const double u = at.u, v = at.v;
  const auto size = static_cast<Eigen::Index>(A_.rows());
  Eigen::MatrixXd control(size, 3);
  for (Eigen::Index i = 0; i < size; ++i) {
    for (int d = 0; d < 3; ++d) control(i, d) = ring[static_cast<std::size_t>(i)][d];
  }
  const auto to_vec = [](const Eigen::RowVector3d& r) { return Vec3{r(0), r(1), r(2)}; };
  std::array<std::vector<double>, 6> weights;
  if (split_ == SplitRule::quad) {
    const PatchWeights<16> b = bicubic_bspline_weights(u, v);
    weights = {{{b.value.begin(), b.value.end()}, {b.du.begin(), b.du.end()}, {b.dv.begin(), b.dv.end()},
                {b.duu.begin(), b.duu.end()}, {b.duv.begin(), b.duv.end()}, {b.dvv.begin(), b.dvv.end()}}};
  } else {
    const PatchWeights<12> b = box_spline_weights(u, v);
    weights = {{{b.value.begin(), b.value.end()}, {b.du.begin(), b.du.end()}, {b.dv.begin(), b.dv.end()},
                {b.duu.begin(), b.duu.end()}, {b.duv.begin(), b.duv.end()}, {b.dvv.begin(), b.dvv.end()}}};
  }
  // The weights of each family over the ring, then the family's point. A
  // derivative of order d is 2^d (2^d lambda)^n in the eigenbasis: scaled
  // there, never 2^(n d) apart, so nothing overflows. Components that a
  // derivative annihilates analytically (the constant one, eigenvalue 1;
  // any whose coefficient is rounding noise, below 1e-13 of the family's
  // largest) are dropped: near the corner they would be rounding errors
  // multiplied by 2^(n d).
  const auto family = [&](const std::vector<double>& family_weights, int order) {
    const Eigen::Map<const Eigen::RowVectorXd> row(family_weights.data(), static_cast<Eigen::Index>(family_weights.size()));
    const double growth = std::ldexp(1.0, order);
    Eigen::RowVectorXd over_ring;
    if (eigenbasis_) {
      Eigen::RowVectorXcd in_basis = row.cast<std::complex<double>>() * child_V_[k];
      const double largest = in_basis.cwiseAbs().maxCoeff();
      for (Eigen::Index i = 0; i < size; ++i) {
        const bool annihilated = order > 0 && (std::abs(eigenvalues_(i) - 1.0) < 1e-12 ||
                                               std::abs(in_basis(i)) < 1e-13 * largest);
        in_basis(i) = annihilated ? 0.0 : in_basis(i) * std::pow(growth * eigenvalues_(i), level);
      }
      over_ring = (in_basis * V_inverse_).real();
    } else {
      over_ring = row * children_[k].rows;
      for (int i = 0; i < level; ++i) over_ring = growth * (over_ring * A_);
    }
    return to_vec(over_ring * control);
  };
  return to_face({family(weights[0], 0), family(weights[1], 1), family(weights[2], 1), family(weights[3], 2),
                  family(weights[4], 2), family(weights[5], 2)},
                 k);
}

}  // namespace subdiv
