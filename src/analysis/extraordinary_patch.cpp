#include "analysis/extraordinary_patch.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "analysis/patch_basis.h"
#include "analysis/patch_points.h"
#include "subdiv/core/error.h"
#include "subdiv/core/stencil_table.h"
#include "subdiv/refine/configuration.h"
#include "subdiv/refine/refine.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/topology/split.h"

namespace subdiv {

std::optional<FaceRing> face_ring(const MeshTopology& topology, Index corner) {
  FaceRing ring;
  std::vector<Index> position_of;  // list position + 1 of each vertex seen; 0: not yet
  position_of.assign(static_cast<std::size_t>(topology.vertex_count()), 0);
  const auto visit_face = [&](Index from) {
    const Index face = topology.corner_face(from);
    ring.signature.push_back(static_cast<int>(topology.face_size(face)));
    Index c = from;
    do {
      const auto v = static_cast<std::size_t>(topology.corner_vertex(c));
      if (position_of[v] == 0) {
        ring.vertices.push_back(static_cast<Index>(v));
        position_of[v] = static_cast<Index>(ring.vertices.size());
      }
      ring.signature.push_back(static_cast<int>(position_of[v]) - 1);
      c = topology.corner_next(c);
    } while (c != from);
  };
  Index c = corner;
  do {
    const Index v = topology.corner_vertex(c);
    if (topology.vertex_kind(v) != VertexKind::interior || topology.fan_count(v) != 1) return std::nullopt;
    // Counter-clockwise around v from the face: across the edge that
    // enters v in each face.
    Index around = c;
    int faces = 0;
    do {
      visit_face(around);
      around = topology.corner_across(topology.corner_prev(around));
      if (around == kInvalidIndex || ++faces > topology.vertex_face_count(v)) return std::nullopt;
    } while (around != c);
    ring.signature.push_back(-1);  // end of the fan
    c = topology.corner_next(c);
  } while (c != corner);
  return ring;
}

namespace {

[[noreturn]] void inconsistent(int valence, const std::string& what) {
  throw std::logic_error("extraordinary patch, valence " + std::to_string(valence) + ": " + what);
}

/// Rows `rows` of `table` as a dense matrix over the ring's columns.
Eigen::MatrixXd rows_over_ring(const StencilTable& table, const std::vector<Index>& rows,
                               const std::vector<int>& column_of, int columns, int valence) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), columns);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto vertices = table.row_vertices(rows[r]);
    const auto weights = table.row_weights(rows[r]);
    for (std::size_t e = 0; e < vertices.size(); ++e) {
      const int column = column_of[static_cast<std::size_t>(vertices[e])];
      if (column < 0) inconsistent(valence, "a child row reads a vertex outside the face ring");
      m(static_cast<Eigen::Index>(r), column) += weights[e];
    }
  }
  return m;
}

}  // namespace

ExtraordinaryPatch::ExtraordinaryPatch(int valence) : valence_(valence) {
  if (valence < 3) throw InvalidInputError("extraordinary patch: valence " + std::to_string(valence) + " is below 3");
  Configuration configuration;
  configuration.kind = Configuration::Kind::interior;
  configuration.k = valence;
  // Four rings keep the ring mesh's boundary rules away from every row read.
  const RingMesh model = ring_mesh(SplitRule::quad, configuration, 4);
  const MeshTopology parent(model.mesh);
  const Index corner = parent.vertex_corners(model.centre)[0];
  const std::optional<FaceRing> ring = face_ring(parent, corner);
  if (!ring || ring->vertices.size() != static_cast<std::size_t>(2 * valence + 8)) {
    inconsistent(valence, "the model face's ring is not 2N + 8 vertices");
  }
  signature_ = ring->signature;
  for (const Index v : ring->vertices) layout_.push_back(model.mesh.positions[static_cast<std::size_t>(v)]);
  const int size = static_cast<int>(ring->vertices.size());
  std::vector<int> column_of(static_cast<std::size_t>(parent.vertex_count()), -1);
  for (int i = 0; i < size; ++i) column_of[static_cast<std::size_t>(ring->vertices[static_cast<std::size_t>(i)])] = i;

  RefineOptions one_step;
  one_step.levels = 1;
  one_step.regular_grids = false;
  const StencilTable table = refine_stencil_table(model.mesh, catmull_clark_scheme(), one_step);
  PolygonMesh child_mesh;
  const SplitMap map = split_topology(model.mesh, parent, SplitRule::quad, child_mesh);
  const MeshTopology child(child_mesh);

  // The parameter of each child vertex of F in F's frame.
  constexpr std::array<std::array<double, 2>, 4> kCorner = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  std::vector<std::array<double, 2>> parameter(static_cast<std::size_t>(child.vertex_count()), {-1.0, -1.0});
  Index c = corner;
  for (std::size_t k = 0; k < 4; ++k, c = parent.corner_next(c)) {
    const auto& [s, t] = kCorner[k];
    const auto& [ns, nt] = kCorner[(k + 1) % 4];
    parameter[static_cast<std::size_t>(map.vertex_point(parent.corner_vertex(c)))] = {s, t};
    parameter[static_cast<std::size_t>(map.edge_point(parent.corner_edge(c)))] = {(s + ns) / 2, (t + nt) / 2};
  }
  parameter[static_cast<std::size_t>(map.face_point(parent.corner_face(corner)))] = {0.5, 0.5};
  const auto corner_at = [&](Index child_face, double s, double t) {
    for (Index k = 0; k < child.face_size(child_face); ++k) {
      const Index cc = child.face_first_corner(child_face) + k;
      const auto& p = parameter[static_cast<std::size_t>(child.corner_vertex(cc))];
      if (p[0] == s && p[1] == t) {
        // The frame must be F's: the next corner half a step along s.
        const auto& q = parameter[static_cast<std::size_t>(child.corner_vertex(child.corner_next(cc)))];
        if (q[0] != s + 0.5 || q[1] != t) inconsistent(valence_, "a child face is not oriented as its parent");
        return cc;
      }
    }
    inconsistent(valence_, "a child face lacks its corner");
  };
  // The quad split's child face at parent corner c is face c.
  const Index centre_child = corner_at(corner, 0.0, 0.0);
  const std::optional<FaceRing> child_ring = face_ring(child, centre_child);
  if (!child_ring || child_ring->signature != signature_) inconsistent(valence_, "the centre child's ring differs");
  A_ = rows_over_ring(table, child_ring->vertices, column_of, size, valence_);
  constexpr std::array<std::array<double, 2>, 3> kChildOrigin = {{{0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}}};
  Index parent_corner = parent.corner_next(corner);
  for (std::size_t k = 0; k < 3; ++k, parent_corner = parent.corner_next(parent_corner)) {
    const Index origin = corner_at(parent_corner, kChildOrigin[k][0], kChildOrigin[k][1]);
    const auto points = bicubic_patch_points(child, origin);
    if (!points) inconsistent(valence_, "a regular child has no bicubic patch");
    child_[k] = rows_over_ring(table, std::vector<Index>(points->begin(), points->end()), column_of, size, valence_);
  }

  // The corner's limit: row 0 (the centre) of A^256, by repeated squaring;
  // the subdominant eigenvalues' 256th powers are below 1e-40.
  Eigen::MatrixXd power = A_;
  for (int i = 0; i < 8; ++i) power = power * power;
  limit_row_ = power.row(0).transpose();

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
        for (std::size_t k = 0; k < 3; ++k) child_V_[k] = child_[k].cast<std::complex<double>>() * V;
      }
    }
  }
}

PatchPoint ExtraordinaryPatch::evaluate(const std::vector<Vec3>& ring, double s, double t) const {
  const auto size = static_cast<Eigen::Index>(A_.rows());
  if (static_cast<Eigen::Index>(ring.size()) != size) {
    throw InvalidInputError("extraordinary patch: " + std::to_string(ring.size()) + " control points for a ring of " +
                            std::to_string(size));
  }
  Eigen::MatrixXd control(size, 3);
  for (Eigen::Index i = 0; i < size; ++i) {
    for (int d = 0; d < 3; ++d) control(i, d) = ring[static_cast<std::size_t>(i)][d];
  }
  const auto to_vec = [](const Eigen::RowVector3d& v) { return Vec3{v(0), v(1), v(2)}; };
  PatchPoint point{};
  if (s == 0.0 && t == 0.0) {
    point.position = to_vec(limit_row_.transpose() * control);
    return point;
  }
  // Level n: the largest whose centre child still holds (s, t) at its
  // edge or outside; doubling is exact in floating point.
  int n = 0;
  while (std::max(s, t) < 0.5) {
    s *= 2.0;
    t *= 2.0;
    ++n;
  }
  const std::size_t k = s >= 0.5 ? (t >= 0.5 ? 1 : 0) : 2;
  constexpr std::array<std::array<double, 2>, 3> kChildOrigin = {{{0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}}};
  const PatchWeights<16> b = bicubic_bspline_weights(2.0 * (s - kChildOrigin[k][0]), 2.0 * (t - kChildOrigin[k][1]));
  // The weights of each family over the ring, then the family's point. A
  // derivative of order d is 2^d (2^d lambda)^n in the eigenbasis: scaled
  // there, never 2^(n d) apart, so nothing overflows. Components that a
  // derivative annihilates analytically (the constant one, eigenvalue 1;
  // any whose coefficient is rounding noise, below 1e-13 of the family's
  // largest) are dropped: near the corner they would be rounding errors
  // multiplied by 2^(n d).
  const auto family = [&](const std::array<double, 16>& weights, int order) {
    const Eigen::Map<const Eigen::Matrix<double, 1, 16>> row(weights.data());
    const double growth = std::ldexp(1.0, order);
    Eigen::RowVectorXd over_ring;
    if (eigenbasis_) {
      Eigen::RowVectorXcd in_basis = row.cast<std::complex<double>>() * child_V_[k];
      const double largest = in_basis.cwiseAbs().maxCoeff();
      for (Eigen::Index i = 0; i < size; ++i) {
        const bool annihilated = order > 0 && (std::abs(eigenvalues_(i) - 1.0) < 1e-12 ||
                                               std::abs(in_basis(i)) < 1e-13 * largest);
        in_basis(i) = annihilated ? 0.0 : in_basis(i) * growth * std::pow(growth * eigenvalues_(i), n);
      }
      over_ring = (in_basis * V_inverse_).real();
    } else {
      over_ring = row * child_[k];
      for (int i = 0; i < n; ++i) over_ring = growth * (over_ring * A_);
      over_ring *= growth;
    }
    return to_vec(over_ring * control);
  };
  point.position = family(b.value, 0);
  point.du = family(b.du, 1);
  point.dv = family(b.dv, 1);
  point.duu = family(b.duu, 2);
  point.duv = family(b.duv, 2);
  point.dvv = family(b.dvv, 2);
  return point;
}

}  // namespace subdiv
