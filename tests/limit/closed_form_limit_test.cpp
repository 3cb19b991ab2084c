// The closed-form limit masks of Catmull-Clark, Loop and loop-warren against
// two independent computations: the analysis (left eigenvectors of the
// local subdivision matrix read off the refinement rules, and the generic
// limit route built on them), and deep refinement (a vertex point approaches
// the closed-form limit at the rate of the subdominant eigenvalue).

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

#include <Eigen/Eigenvalues>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

const Scheme* const kSchemes[] = {&catmull_clark_scheme(), &loop_scheme(), &loop_warren_scheme()};

// A mask as a vector over the analysis neighbourhood (centre, then the ring
// counter-clockwise from the first ray: edge neighbour, then the face's
// opposite vertex, for quads).
Eigen::VectorXd as_vector(const LimitMask& mask, bool quads, Eigen::Index size) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(size);
  v[0] = mask.vertex;
  for (std::size_t i = 0; i < mask.edges.size(); ++i) v[static_cast<Eigen::Index>(quads ? 1 + 2 * i : 1 + i)] = mask.edges[i];
  for (std::size_t j = 0; j < mask.faces.size(); ++j) v[static_cast<Eigen::Index>(2 + 2 * j)] = mask.faces[j];
  return v;
}

// |l S - mu l| / |l| with mu the Rayleigh quotient; returns mu.
double eigen_residual(const Eigen::VectorXd& l, const Eigen::MatrixXd& S, double& mu) {
  const Eigen::VectorXd lS = S.transpose() * l;
  mu = lS.dot(l) / l.squaredNorm();
  return (lS - mu * l).norm() / l.norm();
}

struct Case {
  Configuration configuration;
  VertexNeighbourhood neighbourhood;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (int k = 3; k <= 12; ++k) {
    VertexNeighbourhood n;
    n.edges = n.faces = k;
    n.rule = VertexRule::smooth;
    out.push_back({{Configuration::Kind::interior, k, CornerType::convex}, n});
  }
  for (int k = 1; k <= 6; ++k) {
    VertexNeighbourhood n;
    n.edges = k + 1;
    n.faces = k;
    // The analysis's one-face boundary vertex is a corner (edge-and-corner).
    n.rule = k == 1 ? VertexRule::corner : VertexRule::crease;
    n.sharp[0] = 0;
    n.sharp[1] = k;
    out.push_back({{Configuration::Kind::boundary, k, CornerType::convex}, n});
  }
  return out;
}

// Every mask is an exact left eigenvector of the scheme's local subdivision
// matrix: the position for 1, the tangent along a crease for 1/2, the
// others for the subdominant eigenvalue (interior) or the cross eigenvalue
// of the sector (boundary), which the analysis finds among its leading ones.
TEST(ClosedFormLimit, MasksAreLeftEigenvectorsOfTheLocalSubdivisionMatrix) {
  for (const Scheme* scheme : kSchemes) {
    const bool quads = scheme->split == SplitRule::quad;
    for (const Case& c : cases()) {
      SCOPED_TRACE(std::string(scheme->name) + " " + c.configuration.name());
      AnalysisOptions options;
      options.characteristic_map = false;
      const ConfigurationAnalysis a = analyze(*scheme, c.configuration, options);
      ASSERT_EQ(a.matrix.rings, 1);
      const Eigen::MatrixXd& S = a.matrix.S;
      LimitMasks m;
      ASSERT_TRUE(scheme->limit_masks(c.neighbourhood, m));
      double mu = 0.0;
      const Eigen::VectorXd position = as_vector(m.position, quads, S.rows());
      EXPECT_LT(eigen_residual(position, S, mu), 1e-13);
      EXPECT_NEAR(mu, 1.0, 1e-13);
      EXPECT_NEAR(position.sum(), 1.0, 1e-14);
      if (a.limit_mask) {
        EXPECT_LT((position - *a.limit_mask).norm(), 1e-12);
      }
      for (const LimitMask* t : {&m.tangent1, &m.tangent2}) {
        const Eigen::VectorXd l = as_vector(*t, quads, S.rows());
        EXPECT_LT(eigen_residual(l, S, mu), 1e-13);
        EXPECT_NEAR(l.sum(), 0.0, 1e-13);
        // mu is one of the eigenvalues the analysis lists first.
        bool leading = false;
        for (std::size_t i = 1; i < a.leading.size(); ++i) leading = leading || std::abs(a.leading[i] - mu) < 1e-9;
        EXPECT_TRUE(leading) << "mu = " << mu;
      }
      if (c.configuration.kind == Configuration::Kind::interior) {
        const int k = c.configuration.k;
        const double lambda = quads ? catmull_clark_subdominant_eigenvalue(k)
                                    : 0.375 + 0.25 * std::cos(2.0 * std::numbers::pi / k);
        EXPECT_LT(eigen_residual(as_vector(m.tangent1, quads, S.rows()), S, mu), 1e-13);
        EXPECT_NEAR(mu, lambda, 1e-13);
        EXPECT_NEAR(std::abs(a.leading[1]), lambda, 1e-10);
      }
    }
  }
}

// A ring mesh with its vertices moved off the plane, reproducibly.
PolygonMesh jittered(PolygonMesh mesh, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> d(-0.2, 0.2);
  for (Vec3& p : mesh.positions) p += Vec3{d(random), d(random), 2.0 * d(random)};
  return mesh;
}

// The closed-form route against the generic route on the same meshes:
// positions everywhere; normals where the analysis's tangent pair spans the
// tangent plane the closed forms describe (interior; boundary where the
// curve's 1/2 is one of the two subdominant eigenvalues).
TEST(ClosedFormLimit, AgreesWithTheGenericMasks) {
  for (const Scheme* scheme : kSchemes) {
    for (const Case& c : cases()) {
      // The generic route has no configuration for a one-face boundary vertex.
      if (c.configuration.kind == Configuration::Kind::boundary && c.configuration.k == 1) continue;
      SCOPED_TRACE(std::string(scheme->name) + " " + c.configuration.name());
      RingMesh ring = ring_mesh(scheme->split, c.configuration, 2);
      ring.mesh = jittered(ring.mesh, 7u * static_cast<unsigned>(c.configuration.k));
      LimitOptions closed, generic;
      closed.refine.boundary = generic.refine.boundary = BoundaryInterpolation::edge_only;
      generic.route = LimitRoute::generic;
      generic.isolation_levels = 0;
      const LimitResult a = limit_positions(ring.mesh, *scheme, closed);
      const LimitResult b = limit_positions(ring.mesh, *scheme, generic);
      const auto v = static_cast<std::size_t>(ring.centre);
      ASSERT_EQ(a.sources[v], LimitSource::closed_form);
      ASSERT_EQ(b.sources[v], LimitSource::generic);
      EXPECT_LT(norm(a.positions[v] - b.positions[v]), 1e-12);
      AnalysisOptions options;
      options.characteristic_map = false;
      const ConfigurationAnalysis an = analyze(*scheme, c.configuration, options);
      const bool curve_subdominant = std::abs(an.leading[1] - 0.5) < 1e-9 ||
                                     (std::abs(an.leading[2] - 0.5) < 1e-9 && std::abs(an.leading[3]) < 0.5 - 1e-9);
      if (c.configuration.kind == Configuration::Kind::interior || curve_subdominant) {
        ASSERT_GT(norm(b.normals[v]), 0.5);
        EXPECT_GT(dot(a.normals[v], b.normals[v]), 1.0 - 1e-12) << "normals differ";
      }
    }
  }
}

// The distances d_L = |vertex point after L levels - closed-form limit|, for
// the centre of a jittered ring mesh.
std::vector<double> distances_to_limit(const Scheme& scheme, const PolygonMesh& mesh, Index centre, int levels) {
  LimitOptions options;
  options.refine.boundary = BoundaryInterpolation::edge_only;
  const LimitResult limit = limit_positions(mesh, scheme, options);
  EXPECT_EQ(limit.sources[static_cast<std::size_t>(centre)], LimitSource::closed_form);
  const Vec3 target = limit.positions[static_cast<std::size_t>(centre)];
  RefineOptions one;
  one.levels = 1;
  one.boundary = BoundaryInterpolation::edge_only;
  std::vector<double> d;
  PolygonMesh current = mesh;
  Index v = centre;
  for (int l = 0; l <= levels; ++l) {
    d.push_back(norm(current.positions[static_cast<std::size_t>(v)] - target));
    if (l == levels) break;
    const MeshTopology t(current);
    v += (scheme.split == SplitRule::quad ? t.face_count() : 0) + t.edge_count();  // its vertex point
    current = refine(current, scheme, one);
  }
  return d;
}

// The rate at which the centre's vertex point approaches its limit: the
// largest |lambda| < 1 of S whose eigenvector moves the centre, i.e. with
// e_0 having a component along it (e_0^T S^L = sum_j lambda_j^L R_0j L_j).
// The subdominant eigenvectors vanish at the centre (the characteristic
// map's origin), so this is below lambda_1 at smooth vertices.
double centre_rate(const Eigen::MatrixXd& S) {
  const Eigen::EigenSolver<Eigen::MatrixXd> es(S);
  const Eigen::MatrixXcd R = es.eigenvectors();
  const Eigen::MatrixXcd L = R.inverse();
  double rate = 0.0;
  for (Eigen::Index j = 0; j < S.rows(); ++j) {
    const double lambda = std::abs(es.eigenvalues()[j]);
    if (lambda < 1.0 - 1e-9 && std::abs(R(0, j)) * L.row(j).norm() > 1e-8) rate = std::max(rate, lambda);
  }
  return rate;
}

// Deep refinement: d_{L+1} / d_L tends to the centre's rate from the
// analysis's matrix. A wrong limit would leave d_L at the error and the
// ratio would tend to 1.
TEST(ClosedFormLimit, RefinementConvergesAtTheSubdominantRate) {
  struct Deep {
    const Scheme* scheme;
    Configuration configuration;
  };
  const Deep deep[] = {
      {&catmull_clark_scheme(), {Configuration::Kind::interior, 3, CornerType::convex}},
      {&catmull_clark_scheme(), {Configuration::Kind::interior, 5, CornerType::convex}},
      {&catmull_clark_scheme(), {Configuration::Kind::boundary, 3, CornerType::convex}},
      {&loop_scheme(), {Configuration::Kind::interior, 3, CornerType::convex}},
      {&loop_scheme(), {Configuration::Kind::interior, 7, CornerType::convex}},
      {&loop_scheme(), {Configuration::Kind::boundary, 5, CornerType::convex}},
      {&loop_warren_scheme(), {Configuration::Kind::interior, 5, CornerType::convex}},
  };
  constexpr int kLevels = 7;
  for (const Deep& c : deep) {
    SCOPED_TRACE(std::string(c.scheme->name) + " " + c.configuration.name());
    const RingMesh ring = ring_mesh(c.scheme->split, c.configuration, 2);
    const std::vector<double> d = distances_to_limit(*c.scheme, jittered(ring.mesh, 11u), ring.centre, kLevels);
    AnalysisOptions options;
    options.characteristic_map = false;
    const ConfigurationAnalysis a = analyze(*c.scheme, c.configuration, options);
    const double lambda = centre_rate(a.matrix.S);
    const double ratio = d[kLevels] / d[kLevels - 1];
    std::cout << "[ MEASURED ] " << c.scheme->name << " " << c.configuration.name() << ": d_" << kLevels << " = "
              << d[kLevels] << ", d_" << kLevels << "/d_" << kLevels - 1 << " = " << ratio
              << ", centre rate = " << lambda << " (lambda_1 = " << std::abs(a.leading[1]) << ")\n";
    EXPECT_LT(lambda, 1.0);
    EXPECT_NEAR(ratio, lambda, 0.02 * lambda);
    EXPECT_LT(d[kLevels], 2.0 * std::pow(lambda, kLevels) * d[0] + 1e-14);
  }
}

}  // namespace
}  // namespace subdiv
