// The Doo-Sabin bound at extraordinary faces: the face's local operator,
// finding its neighbourhood in a mesh, and the amplitude that powers of the
// local subdivision matrix give (src/depth/dual_face_bound.h;
// docs/depth.md, "Doo-Sabin").

#include "depth/dual_face_bound.h"

#include <Eigen/Eigenvalues>
#include <array>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "subdiv/analysis/analyze.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/refine/subdivision_matrix.h"
#include "subdiv/core/error.h"

namespace subdiv {

namespace {

constexpr double kLayoutTolerance = 1e-9;

std::string face_name(int k) { return "the face of " + std::to_string(k) + " sides"; }

// The left eigenvector of S for eigenvalue 1, scaled so that it sums to 1
// (the limit mask over the neighbourhood).
Eigen::RowVectorXd limit_functional(const Eigen::MatrixXd& S, int k) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(S.transpose());
  Eigen::Index best = 0;
  for (Eigen::Index i = 1; i < solver.eigenvalues().size(); ++i)
    if (std::abs(solver.eigenvalues()[i] - 1.0) < std::abs(solver.eigenvalues()[best] - 1.0)) best = i;
  if (std::abs(solver.eigenvalues()[best] - 1.0) > 1e-9)
    throw InvalidInputError("no eigenvalue 1 in the subdivision matrix of " + face_name(k));
  Eigen::RowVectorXd l = solver.eigenvectors().col(best).real().transpose();
  return l / l.sum();
}

// The functionals of face f's neighbourhood in mesh t (column(v) >= 0 on
// its vertices): vertex-to-limit functionals of f's vertices (interior: the
// centroid of the V-face one step down, whose corner points are rows of
// `step`, the child of corner c being child vertex c; boundary: the
// boundary curve's limit (a + 6 v + b) / 8) and the second differences along
// the mesh lines (opposite edges of a 4-valent interior vertex, the two
// boundary edges of a 3-valent boundary vertex) inside the neighbourhood.
template <typename Column>
void add_functionals(const MeshTopology& t, Index f, const StencilTable& step, const std::array<double, 3>& boundary,
                     Column column, Eigen::Index n, DualFaceOperator& op) {
  const auto sparse = [&](const Eigen::RowVectorXd& row) {
    DualFaceOperator::SparseRow out;
    for (Eigen::Index j = 0; j < n; ++j)
      if (row[j] != 0.0) out.emplace_back(j, row[j]);
    return out;
  };
  for (const Index v : t.face_vertices(f)) {
    Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n);
    row[column(v)] -= 1.0;
    if (t.vertex_kind(v) == VertexKind::boundary) {
      const auto edges = t.vertex_edges(v);
      row[column(t.other_vertex(edges.front(), v))] += boundary[0];
      row[column(v)] += boundary[1];
      row[column(t.other_vertex(edges.back(), v))] += boundary[2];
    } else {
      const auto corners = t.vertex_corners(v);
      for (const Index c : corners) {
        const auto vertices = step.row_vertices(c);
        const auto weights = step.row_weights(c);
        for (std::size_t e = 0; e < vertices.size(); ++e) {
          if (column(vertices[e]) < 0)
            throw InvalidInputError(face_name(op.k) + ": a corner point reaches outside its two-ring neighbourhood");
          row[column(vertices[e])] += weights[e] / static_cast<double>(corners.size());
        }
      }
    }
    op.distance.push_back(sparse(row));
  }
  for (Index v = 0; v < t.vertex_count(); ++v) {
    if (column(v) < 0 || !t.ring_ordered(v)) continue;
    const auto edges = t.vertex_edges(v);
    const auto line = [&](std::size_t i, std::size_t j) {
      const Index a = t.other_vertex(edges[i], v), b = t.other_vertex(edges[j], v);
      if (column(a) >= 0 && column(b) >= 0)
        op.second_difference.push_back({{column(a), 1.0}, {column(v), -2.0}, {column(b), 1.0}});
    };
    if (t.vertex_kind(v) == VertexKind::interior && edges.size() == 4) {
      line(0, 2);
      line(1, 3);
    } else if (t.vertex_kind(v) == VertexKind::boundary && edges.size() == 3) {
      line(0, 2);
    }
  }
}

// The pattern of face f's neighbourhood in mesh t: breadth first across
// edges from f over the faces touching its one-ring, with the boundary
// edges, kinds and face counts a match must reproduce.
template <typename Column>
DualFaceOperator::Pattern neighbourhood_pattern(const MeshTopology& t, Index f, Column column) {
  const std::vector<int> rings = vertex_rings(t, t.face_vertices(f), 1);
  std::vector<char> wanted(static_cast<std::size_t>(t.face_count()), 0);
  for (Index v = 0; v < t.vertex_count(); ++v)
    if (rings[static_cast<std::size_t>(v)] >= 0)
      for (const Index c : t.vertex_corners(v)) wanted[static_cast<std::size_t>(t.corner_face(c))] = 1;
  DualFaceOperator::Pattern pattern;
  std::vector<int> step_of(static_cast<std::size_t>(t.face_count()), -1);
  std::vector<Index> face_of_step;
  const auto add_step = [&](Index g, int from, int from_corner, int corner) {
    DualFaceOperator::Step s;
    s.from = from;
    s.from_corner = from_corner;
    s.corner = corner;
    for (Index c = t.face_first_corner(g); c < t.face_first_corner(g) + t.face_size(g); ++c) {
      if (column(t.corner_vertex(c)) < 0)
        throw InvalidInputError(face_name(t.face_size(f)) + ": a face of the one-ring reaches outside the neighbourhood");
      s.columns.push_back(column(t.corner_vertex(c)));
      s.boundary.push_back(t.corner_across(c) == kInvalidIndex ? 1 : 0);
    }
    step_of[static_cast<std::size_t>(g)] = static_cast<int>(pattern.steps.size());
    face_of_step.push_back(g);
    pattern.steps.push_back(std::move(s));
  };
  add_step(f, -1, 0, 0);
  for (std::size_t i = 0; i < pattern.steps.size(); ++i) {
    const Index g = face_of_step[i];
    for (int a = 0; a < t.face_size(g); ++a) {
      const Index other = t.corner_across(t.face_first_corner(g) + a);
      if (other == kInvalidIndex) continue;
      const Index h = t.corner_face(other);
      if (!wanted[static_cast<std::size_t>(h)] || step_of[static_cast<std::size_t>(h)] >= 0) continue;
      add_step(h, static_cast<int>(i), a, static_cast<int>(other - t.face_first_corner(h)));
    }
  }
  for (Index h = 0; h < t.face_count(); ++h)
    if (wanted[static_cast<std::size_t>(h)] && step_of[static_cast<std::size_t>(h)] < 0)
      throw InvalidInputError(face_name(t.face_size(f)) + ": a face of the one-ring is not reached across edges");
  for (Index v = 0; v < t.vertex_count(); ++v) {
    if (rings[static_cast<std::size_t>(v)] < 0) continue;
    const Index c = t.vertex_corners(v).front();
    pattern.one_ring.push_back({step_of[static_cast<std::size_t>(t.corner_face(c))],
                                static_cast<int>(c - t.face_first_corner(t.corner_face(c))), t.vertex_kind(v),
                                t.vertex_face_count(v)});
  }
  return pattern;
}

// The mesh vertex of each of the pattern's `n` columns around face f, or
// nothing where t differs from the pattern there.
std::optional<std::vector<Index>> match(const DualFaceOperator::Pattern& pattern, const MeshTopology& t, Index f,
                                        Eigen::Index n) {
  if (t.face_size(f) != static_cast<Index>(pattern.steps.front().columns.size())) return std::nullopt;
  std::vector<Index> face(pattern.steps.size()), corner0(pattern.steps.size());
  const auto corner_at = [&](std::size_t s, int local) {
    const Index first = t.face_first_corner(face[s]);
    return first + (corner0[s] - first + local) % t.face_size(face[s]);
  };
  face[0] = f;
  corner0[0] = t.face_first_corner(f);
  std::vector<Index> vertex_of(static_cast<std::size_t>(n), kInvalidIndex);
  for (std::size_t s = 0; s < pattern.steps.size(); ++s) {
    const DualFaceOperator::Step& step = pattern.steps[s];
    if (s > 0) {
      const Index other = t.corner_across(corner_at(static_cast<std::size_t>(step.from), step.from_corner));
      if (other == kInvalidIndex) return std::nullopt;
      face[s] = t.corner_face(other);
      const Index size = t.face_size(face[s]);
      if (size != static_cast<Index>(step.columns.size())) return std::nullopt;
      const Index local = other - t.face_first_corner(face[s]);
      corner0[s] = t.face_first_corner(face[s]) + ((local - step.corner) % size + size) % size;
    }
    for (std::size_t i = 0; i < step.columns.size(); ++i) {
      const Index c = corner_at(s, static_cast<int>(i));
      if ((t.corner_across(c) == kInvalidIndex) != (step.boundary[i] != 0)) return std::nullopt;
      Index& mapped = vertex_of[static_cast<std::size_t>(step.columns[i])];
      if (mapped != kInvalidIndex && mapped != t.corner_vertex(c)) return std::nullopt;
      mapped = t.corner_vertex(c);
    }
  }
  for (const DualFaceOperator::OneRingVertex& r : pattern.one_ring) {
    const Index w = t.corner_vertex(corner_at(static_cast<std::size_t>(r.step), r.corner));
    if (t.vertex_kind(w) != r.kind || t.vertex_face_count(w) != r.faces) return std::nullopt;
  }
  std::vector<Index> sorted = vertex_of;
  std::sort(sorted.begin(), sorted.end());
  if (sorted.front() == kInvalidIndex || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    return std::nullopt;  // a column unreached, or the neighbourhood wraps around onto itself
  return vertex_of;
}

}  // namespace

DualFaceOperator dual_face_operator(const Scheme& scheme, int k, const RefineOptions& rules) {
  if (scheme.split != SplitRule::dual)
    throw InvalidInputError(std::string(scheme.name) + ": the face bound needs a dual-split scheme");
  const Configuration face{Configuration::Kind::interior, k, CornerType::convex};
  const LocalSubdivisionMatrix m = local_subdivision_matrix(scheme, face, kDualBoundRings, rules);
  if (!m.invariant)
    throw InvalidInputError(std::string(scheme.name) + ": the two-ring neighbourhood of " + face_name(k) +
                            " is not invariant: " + m.invariance_note);
  AnalysisOptions analysis;
  analysis.characteristic_map = false;
  analysis.regular_rules = false;  // the spectrum alone
  analysis.rules = rules;
  const ConfigurationAnalysis spectrum = analyze(scheme, face, analysis);
  if (spectrum.leading.size() < 2 || !(std::abs(spectrum.leading[1]) > 0.0))
    throw InvalidInputError(std::string(scheme.name) + ": the analysis of " + face_name(k) +
                            " found no subdominant eigenvalue");
  DualFaceOperator op;
  op.k = k;
  op.rate = std::abs(spectrum.leading[1]);
  op.S = m.S;
  op.limit = limit_functional(m.S, k);

  // The ring mesh the matrix was read off, its vertices matched to the
  // matrix's columns by their layout points.
  const RingMesh ring = ring_mesh(SplitRule::dual, face, ring_mesh_size(kDualBoundRings));
  const MeshTopology t(ring.mesh);
  const auto n = static_cast<Eigen::Index>(m.layout.size());
  std::vector<Eigen::Index> column(static_cast<std::size_t>(t.vertex_count()), -1);
  for (Index v = 0; v < t.vertex_count(); ++v)
    for (Eigen::Index j = 0; j < n; ++j)
      if (norm(m.layout[static_cast<std::size_t>(j)] - ring.mesh.positions[static_cast<std::size_t>(v)]) <
          kLayoutTolerance)
        column[static_cast<std::size_t>(v)] = j;
  const auto col = [&](Index v) { return column[static_cast<std::size_t>(v)]; };
  Scheme open = scheme;  // the ring mesh's outer boundary lies outside the neighbourhood
  open.traits.needs_closed_mesh = false;
  RefineOptions once = rules;
  once.levels = 1;
  once.on_level = nullptr;
  add_functionals(t, ring.centre_face, refine_stencil_table(ring.mesh, open, once), boundary_vertex_limit(scheme), col,
                  n, op);
  op.pattern = neighbourhood_pattern(t, ring.centre_face, col);
  return op;
}

std::optional<Eigen::MatrixXd> canonical_neighbourhood(const DualFaceOperator& op, const MeshTopology& t,
                                                       const std::vector<Vec3>& positions, Index f) {
  const std::optional<std::vector<Index>> vertices = match(op.pattern, t, f, op.S.rows());
  if (!vertices) return std::nullopt;
  Eigen::MatrixXd out(op.S.rows(), 3);
  for (Eigen::Index j = 0; j < out.rows(); ++j) {
    const Vec3 p = positions[static_cast<std::size_t>((*vertices)[static_cast<std::size_t>(j)])];
    out.row(j) << p.x, p.y, p.z;
  }
  return out;
}

std::optional<DualFaceOperator> local_face_operator(const MeshTopology& parent, const StencilTable& step,
                                                    const MeshTopology& child, Index f,
                                                    const std::array<double, 3>& boundary_limit) {
  const std::vector<int> rings = vertex_rings(parent, parent.face_vertices(f), kDualBoundRings);
  std::vector<Eigen::Index> column(static_cast<std::size_t>(parent.vertex_count()), -1);
  Eigen::Index n = 0;
  for (Index v = 0; v < parent.vertex_count(); ++v)
    if (rings[static_cast<std::size_t>(v)] >= 0) column[static_cast<std::size_t>(v)] = n++;
  const auto col = [&](Index v) { return column[static_cast<std::size_t>(v)]; };
  DualFaceOperator op;
  op.k = parent.face_size(f);
  op.pattern = neighbourhood_pattern(parent, f, col);
  // The child's neighbourhood must repeat the parent's (then every later
  // one does: a two-ring's structure follows from its parent's one-ring
  // faces), and its rows must stay inside the parent's.
  const std::optional<std::vector<Index>> image = match(op.pattern, child, f, n);
  if (!image) return std::nullopt;
  op.S = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index a = 0; a < n; ++a) {
    const Index row = (*image)[static_cast<std::size_t>(a)];
    const auto vertices = step.row_vertices(row);
    const auto weights = step.row_weights(row);
    for (std::size_t e = 0; e < vertices.size(); ++e) {
      if (col(vertices[e]) < 0) return std::nullopt;
      op.S(a, col(vertices[e])) += weights[e];
    }
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(op.S);
  std::vector<double> moduli;
  for (Eigen::Index i = 0; i < n; ++i) moduli.push_back(std::abs(solver.eigenvalues()[i]));
  std::sort(moduli.rbegin(), moduli.rend());
  if (moduli.size() < 2 || std::abs(moduli[0] - 1.0) > 1e-9 || !(moduli[1] < 1.0 - 1e-9)) return std::nullopt;
  op.rate = moduli[1];
  op.limit = limit_functional(op.S, op.k);
  add_functionals(parent, f, step, boundary_limit, col, n, op);
  return op;
}

Eigen::MatrixXd local_neighbourhood(const MeshTopology& t, const std::vector<Vec3>& positions, Index f) {
  const std::vector<int> rings = vertex_rings(t, t.face_vertices(f), kDualBoundRings);
  std::vector<Vec3> points;
  for (Index v = 0; v < t.vertex_count(); ++v)
    if (rings[static_cast<std::size_t>(v)] >= 0) points.push_back(positions[static_cast<std::size_t>(v)]);
  Eigen::MatrixXd out(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t j = 0; j < points.size(); ++j) out.row(static_cast<Eigen::Index>(j)) << points[j].x, points[j].y, points[j].z;
  return out;
}

double dual_face_amplitude(const DualFaceOperator& op, const Eigen::MatrixXd& neighbourhood, int powers) {
  // X = rate^-m S^m P less its limit point (1 l P): the functionals vanish
  // on constants, and without the limit point rounding is relative to what
  // they measure rather than to the coordinates.
  Eigen::MatrixXd x = neighbourhood;
  const auto strip = [&] { x.rowwise() -= op.limit * x; };
  const auto value = [&](const DualFaceOperator::SparseRow& row) {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (const auto& [j, w] : row) sum += w * x.row(j);
    return sum.norm();
  };
  strip();
  double worst = 0.0;
  std::vector<double> at_power;
  for (int m = 0; m <= powers; ++m) {
    double here = 0.0;
    for (const auto& row : op.distance) here = std::max(here, value(row));
    for (const auto& row : op.second_difference) here = std::max(here, value(row) / 4.0);
    at_power.push_back(here);
    worst = std::max(worst, here);
    x = (op.S * x) / op.rate;
    strip();
  }
  // A defective subdominant eigenvalue would make the sequence grow like m:
  // its supremum is then not reached, and nothing is claimed.
  const std::size_t last = at_power.size() - 1, earlier = last - std::min<std::size_t>(last, 8);
  if (std::abs(at_power[last] - at_power[earlier]) > 1e-9 * std::max(worst, 1e-300))
    throw InvalidInputError(face_name(op.k) + ": the local subdivision matrix's powers do not settle at rate " +
                            std::to_string(op.rate) + " (a defective subdominant eigenvalue)");
  return worst;
}

}  // namespace subdiv
