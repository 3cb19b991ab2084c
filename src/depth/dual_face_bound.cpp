// The Doo-Sabin bound at extraordinary faces: the face's local operator,
// finding its neighbourhood in a mesh, and the amplitude that powers of the
// local subdivision matrix give (include/subdiv/depth/dual_face_bound.h;
// docs/design.md, "Depth").

#include "subdiv/depth/dual_face_bound.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/ring_mesh.h"
#include "subdiv/analysis/subdivision_matrix.h"
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

// Each vertex's ring about face f (0: f's vertices; r: the vertices of the
// faces touching ring r - 1), -1 beyond `rings`: subdivision_matrix.cpp's
// face rings.
std::vector<int> vertex_rings(const MeshTopology& t, Index f, int rings) {
  std::vector<int> ring(static_cast<std::size_t>(t.vertex_count()), -1);
  std::vector<Index> frontier(t.face_vertices(f).begin(), t.face_vertices(f).end());
  for (const Index v : frontier) ring[static_cast<std::size_t>(v)] = 0;
  for (int r = 1; r <= rings; ++r) {
    std::vector<Index> next;
    for (const Index v : frontier)
      for (const Index c : t.vertex_corners(v))
        for (const Index w : t.face_vertices(t.corner_face(c)))
          if (ring[static_cast<std::size_t>(w)] < 0) {
            ring[static_cast<std::size_t>(w)] = r;
            next.push_back(w);
          }
    frontier = std::move(next);
  }
  return ring;
}

// The other side of corner c's outgoing edge, or kInvalidIndex at a
// boundary or non-manifold edge.
Index across(const MeshTopology& t, Index c) {
  const auto sides = t.edge_corners(t.corner_edge(c));
  if (sides.size() != 2) return kInvalidIndex;
  return sides[0] == c ? sides[1] : sides[0];
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

  // Vertex-to-limit functionals: the V-face's corner points are rows of the
  // scheme's own refinement of the ring mesh (dual split: the child of
  // corner c is child vertex c).
  Scheme open = scheme;
  open.needs_closed_mesh = false;
  RefineOptions once = rules;
  once.levels = 1;
  once.on_level = nullptr;
  const StencilTable step = refine_stencil_table(ring.mesh, open, once);
  for (const Index v : t.face_vertices(ring.centre_face)) {
    Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n);
    row[col(v)] -= 1.0;
    const auto corners = t.vertex_corners(v);
    for (const Index c : corners) {
      const auto vertices = step.row_vertices(c);
      const auto weights = step.row_weights(c);
      for (std::size_t e = 0; e < vertices.size(); ++e) {
        if (col(vertices[e]) < 0)
          throw InvalidInputError(std::string(scheme.name) + ": a corner point of " + face_name(k) +
                                  " reaches outside its two-ring neighbourhood");
        row[col(vertices[e])] += weights[e] / static_cast<double>(corners.size());
      }
    }
    DualFaceOperator::SparseRow sparse;
    for (Eigen::Index j = 0; j < n; ++j)
      if (row[j] != 0.0) sparse.emplace_back(j, row[j]);
    op.distance.push_back(std::move(sparse));
  }
  // Second differences along the mesh lines (opposite edges of a 4-valent
  // vertex's counter-clockwise ring).
  for (Index v = 0; v < t.vertex_count(); ++v) {
    if (col(v) < 0 || t.vertex_kind(v) != VertexKind::interior || !t.ring_ordered(v)) continue;
    const auto edges = t.vertex_edges(v);
    if (edges.size() != 4) continue;
    for (std::size_t j = 0; j < 2; ++j) {
      const Index a = t.other_vertex(edges[j], v), b = t.other_vertex(edges[j + 2], v);
      if (col(a) >= 0 && col(b) >= 0) op.second_difference.push_back({{col(a), 1.0}, {col(v), -2.0}, {col(b), 1.0}});
    }
  }

  // The matching script: breadth first across edges from the centre face
  // over the faces touching its one-ring.
  const std::vector<int> rings = vertex_rings(t, ring.centre_face, 1);
  std::vector<char> wanted(static_cast<std::size_t>(t.face_count()), 0);
  for (Index v = 0; v < t.vertex_count(); ++v)
    if (rings[static_cast<std::size_t>(v)] >= 0)
      for (const Index c : t.vertex_corners(v)) wanted[static_cast<std::size_t>(t.corner_face(c))] = 1;
  std::vector<int> step_of(static_cast<std::size_t>(t.face_count()), -1);
  std::vector<Index> face_of_step;
  const auto add_step = [&](Index g, int from, int from_corner, int corner) {
    DualFaceOperator::Step s;
    s.from = from;
    s.from_corner = from_corner;
    s.corner = corner;
    for (const Index w : t.face_vertices(g)) {
      if (col(w) < 0) throw InvalidInputError(face_name(k) + ": a face of the one-ring reaches outside the neighbourhood");
      s.columns.push_back(col(w));
    }
    step_of[static_cast<std::size_t>(g)] = static_cast<int>(op.steps.size());
    face_of_step.push_back(g);
    op.steps.push_back(std::move(s));
  };
  add_step(ring.centre_face, -1, 0, 0);
  for (std::size_t i = 0; i < op.steps.size(); ++i) {
    const Index g = face_of_step[i];
    const Index first = t.face_first_corner(g);
    for (int a = 0; a < t.face_size(g); ++a) {
      const Index other = across(t, first + a);
      if (other == kInvalidIndex) continue;
      const Index h = t.corner_face(other);
      if (!wanted[static_cast<std::size_t>(h)] || step_of[static_cast<std::size_t>(h)] >= 0) continue;
      add_step(h, static_cast<int>(i), a, static_cast<int>(other - t.face_first_corner(h)));
    }
  }
  for (Index h = 0; h < t.face_count(); ++h)
    if (wanted[static_cast<std::size_t>(h)] && step_of[static_cast<std::size_t>(h)] < 0)
      throw InvalidInputError(face_name(k) + ": a face of the one-ring is not reached across edges");
  for (Index v = 0; v < t.vertex_count(); ++v) {
    if (rings[static_cast<std::size_t>(v)] < 0) continue;
    const Index c = t.vertex_corners(v).front();
    op.one_ring.emplace_back(step_of[static_cast<std::size_t>(t.corner_face(c))],
                             static_cast<int>(c - t.face_first_corner(t.corner_face(c))));
  }
  return op;
}

std::optional<Eigen::MatrixXd> canonical_neighbourhood(const DualFaceOperator& op, const MeshTopology& t,
                                                       const std::vector<Vec3>& positions, Index f) {
  if (t.face_size(f) != op.k) return std::nullopt;
  // The mesh face of each step and the mesh corner of its local corner 0.
  std::vector<Index> face(op.steps.size()), corner0(op.steps.size());
  const auto corner_at = [&](std::size_t s, int local) {
    const Index size = t.face_size(face[s]);
    return t.face_first_corner(face[s]) + (corner0[s] - t.face_first_corner(face[s]) + local) % size;
  };
  face[0] = f;
  corner0[0] = t.face_first_corner(f);
  const auto n = op.S.rows();
  std::vector<Index> vertex_of(static_cast<std::size_t>(n), kInvalidIndex);
  for (std::size_t s = 0; s < op.steps.size(); ++s) {
    const DualFaceOperator::Step& step = op.steps[s];
    if (s > 0) {
      const Index other = across(t, corner_at(static_cast<std::size_t>(step.from), step.from_corner));
      if (other == kInvalidIndex) return std::nullopt;
      face[s] = t.corner_face(other);
      if (t.face_size(face[s]) != static_cast<Index>(step.columns.size())) return std::nullopt;
      const Index size = t.face_size(face[s]);
      const Index local = other - t.face_first_corner(face[s]);
      corner0[s] = t.face_first_corner(face[s]) + ((local - step.corner) % size + size) % size;
    }
    for (std::size_t i = 0; i < step.columns.size(); ++i) {
      const Index w = t.corner_vertex(corner_at(s, static_cast<int>(i)));
      Index& mapped = vertex_of[static_cast<std::size_t>(step.columns[i])];
      if (mapped != kInvalidIndex && mapped != w) return std::nullopt;
      mapped = w;
    }
  }
  for (const auto& [s, local] : op.one_ring) {
    const Index w = t.corner_vertex(corner_at(static_cast<std::size_t>(s), local));
    if (t.vertex_kind(w) != VertexKind::interior || t.vertex_face_count(w) != 4) return std::nullopt;
  }
  std::vector<Index> sorted = vertex_of;
  std::sort(sorted.begin(), sorted.end());
  if (sorted.front() == kInvalidIndex || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    return std::nullopt;  // a column unreached, or the neighbourhood wraps around onto itself
  Eigen::MatrixXd out(n, 3);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Vec3 p = positions[static_cast<std::size_t>(vertex_of[static_cast<std::size_t>(j)])];
    out.row(j) << p.x, p.y, p.z;
  }
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
  for (int m = 0; m <= powers; ++m) {
    for (const auto& row : op.distance) worst = std::max(worst, value(row));
    for (const auto& row : op.second_difference) worst = std::max(worst, value(row) / 4.0);
    x = (op.S * x) / op.rate;
    strip();
  }
  return worst;
}

}  // namespace subdiv
