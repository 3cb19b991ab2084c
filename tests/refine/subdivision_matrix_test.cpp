// Local subdivision matrices read off the real rules, checked against the
// closed forms of Loop and Catmull-Clark.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "subdiv/refine/ring_mesh.h"
#include "subdiv/refine/subdivision_matrix.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"

namespace subdiv {
namespace {

Configuration interior(int k) { return {Configuration::Kind::interior, k, CornerType::convex}; }

// Eigenvalue magnitudes, largest first (the tests use real spectra).
std::vector<double> sorted_eigenvalues(const Eigen::MatrixXd& S) {
  const Eigen::VectorXcd values = S.eigenvalues();
  std::vector<double> out;
  for (const auto& v : values) out.push_back(v.real());
  std::sort(out.begin(), out.end(), [](double a, double b) { return std::fabs(a) > std::fabs(b); });
  return out;
}

TEST(RingMesh, SectorsAroundTheCentre) {
  for (const SplitRule split : {SplitRule::quad, SplitRule::triangle})
    for (const int k : {3, 5, 8}) {
      const RingMesh ring = ring_mesh(split, interior(k), 3);
      const MeshTopology t(ring.mesh);
      EXPECT_TRUE(validate(ring.mesh).ok());
      EXPECT_EQ(t.valence(ring.centre), k);
      EXPECT_EQ(t.vertex_kind(ring.centre), VertexKind::interior);
      EXPECT_EQ(ring.mesh.face_count(), split == SplitRule::quad ? 9 * k : 9 * k);
    }
  const RingMesh boundary = ring_mesh(SplitRule::quad, {Configuration::Kind::boundary, 3, CornerType::convex}, 2);
  const MeshTopology t(boundary.mesh);
  EXPECT_EQ(t.vertex_kind(boundary.centre), VertexKind::boundary);
  EXPECT_EQ(t.vertex_face_count(boundary.centre), 3);
  EXPECT_THROW(ring_mesh(SplitRule::quad, interior(2), 2), InvalidInputError);
}

TEST(SubdivisionMatrix, LoopOneRingHasTheClosedFormSpectrum) {
  for (int k = 3; k <= 12; ++k) {
    const LocalSubdivisionMatrix m = invariant_subdivision_matrix(loop_scheme(), interior(k));
    ASSERT_TRUE(m.invariant) << m.invariance_note;
    EXPECT_EQ(m.rings, 1);
    ASSERT_EQ(m.S.rows(), k + 1);
    // Every row sums to one (affine invariance).
    for (Eigen::Index r = 0; r < m.S.rows(); ++r) EXPECT_NEAR(m.S.row(r).sum(), 1.0, 1e-14);
    // 1, 5/8 - k beta, and 3/8 + 1/4 cos(2 pi j / k), j = 1 .. k - 1.
    std::vector<double> expected{1.0, 0.625 - k * loop_beta(k)};
    for (int j = 1; j < k; ++j) expected.push_back(0.375 + 0.25 * std::cos(2.0 * std::numbers::pi * j / k));
    std::sort(expected.begin(), expected.end(), [](double a, double b) { return std::fabs(a) > std::fabs(b); });
    const std::vector<double> got = sorted_eigenvalues(m.S);
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-12) << "k=" << k << " i=" << i;
  }
}

// Catmull-Clark's subdominant eigenvalue on the 2k + 1 ring (Stam 1998;
// Halstead, Kass and DeRose 1993): (5 + cos(2 pi/k) + cos(pi/k) sqrt(2 (9 + cos(2 pi/k)))) / 16.
TEST(SubdivisionMatrix, CatmullClarkOneRingSubdominantEigenvalue) {
  for (int k = 3; k <= 12; ++k) {
    const LocalSubdivisionMatrix m = invariant_subdivision_matrix(catmull_clark_scheme(), interior(k));
    ASSERT_TRUE(m.invariant) << m.invariance_note;
    ASSERT_EQ(m.S.rows(), 2 * k + 1);
    const double c = std::cos(2.0 * std::numbers::pi / k);
    const double lambda = (5.0 + c + std::cos(std::numbers::pi / k) * std::sqrt(2.0 * (9.0 + c))) / 16.0;
    const std::vector<double> got = sorted_eigenvalues(m.S);
    EXPECT_NEAR(got[0], 1.0, 1e-12);
    EXPECT_NEAR(got[1], lambda, 1e-12) << "k=" << k;
    EXPECT_NEAR(got[2], lambda, 1e-12) << "k=" << k;
    EXPECT_LT(std::fabs(got[3]), lambda - 1e-6);
  }
}

// Every surface scheme's rules are symmetric under rotation of the ring: at
// valences 3, 5 and 7 the matrix (of one period) commutes with the rotation
// by 2 pi / k. A mask that favoured one spoke, or a ring read in the wrong
// order, breaks this. Schemes the ring layout does not cover say so (only
// quasi 4-8, whose split follows the geometry); every other must be checked.
TEST(SubdivisionMatrix, EverySchemeIsSymmetricUnderRotationOfTheRing) {
  std::vector<std::string> checked;
  for (const Scheme* s : all_schemes()) {
    bool covered = true;
    for (const int k : {3, 5, 7}) {
      LocalSubdivisionMatrix m;
      try {
        m = local_subdivision_matrix(*s, interior(k), 2);
      } catch (const InvalidInputError&) {
        covered = false;
        break;
      }
      ASSERT_EQ(m.rotate.size(), static_cast<std::size_t>(m.S.rows())) << s->name << " k=" << k;
      Eigen::MatrixXd P = Eigen::MatrixXd::Zero(m.S.rows(), m.S.cols());
      for (std::size_t i = 0; i < m.rotate.size(); ++i) P(m.rotate[i], static_cast<Eigen::Index>(i)) = 1.0;
      EXPECT_LT((P * m.S - m.S * P).norm(), 1e-12 * std::max(1.0, m.S.norm())) << s->name << " k=" << k;
    }
    if (covered) checked.emplace_back(s->name);
  }
  for (const char* name : {"catmull-clark", "loop", "loop-warren", "butterfly", "modified-butterfly", "doo-sabin",
                           "midedge", "sqrt3", "interpolatory-sqrt3", "kobbelt", "four-eight", "gcc", "midpoint",
                           "bilinear", "linear"})
    EXPECT_NE(std::find(checked.begin(), checked.end(), name), checked.end()) << name << " was not checked";
}

// A made-up scheme whose vertex points reach two rings out: its vertex point
// in an r-ring's image comes from a parent vertex within r/2 rings, so the
// 1- and 2-rings are not invariant and the 3-ring is; the analysis must find
// that out.
void wide_vertex_point(const LevelView& level, Index v, VertexRule, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  mask.add(v, 0.5);
  const double k = t.valence(v);
  for (const Index e : t.vertex_edges(v)) {
    const Index w = t.other_vertex(e, v);
    for (const Index e2 : t.vertex_edges(w)) mask.add(t.other_vertex(e2, w), 0.5 / (k * t.valence(w)));
  }
}

TEST(SubdivisionMatrix, ReportsANeighbourhoodThatIsNotInvariant) {
  const Scheme& cc = catmull_clark_scheme();
  const Scheme wide{.name = "wide",
                    .split = SplitRule::quad,
                    .masks = {.face_point = cc.masks.face_point,
                              .edge_point = cc.masks.edge_point,
                              .vertex_point = wide_vertex_point}};
  const LocalSubdivisionMatrix two = invariant_subdivision_matrix(wide, interior(4), 2);
  EXPECT_FALSE(two.invariant);
  EXPECT_EQ(two.rings, 2);
  EXPECT_NE(two.invariance_note.find("outside the 2-ring"), std::string::npos) << two.invariance_note;
  const LocalSubdivisionMatrix three = invariant_subdivision_matrix(wide, interior(4), 4);
  EXPECT_TRUE(three.invariant);
  EXPECT_EQ(three.rings, 3);
}

TEST(SubdivisionMatrix, InvarianceIsCheckedNotAssumed) {
  // Catmull-Clark's 1-ring is invariant; a neighbourhood of the centre alone
  // would not be, and a 2-ring (6k + 1 vertices) is invariant too.
  const LocalSubdivisionMatrix two = local_subdivision_matrix(catmull_clark_scheme(), interior(4), 2);
  EXPECT_TRUE(two.invariant);
  EXPECT_EQ(two.S.rows(), 6 * 4 + 1);
  // The regular case is the bicubic B-spline: 1, 1/2, 1/2, 1/4, 1/4, 1/4, ...
  const std::vector<double> got = sorted_eigenvalues(two.S);
  const double expected[] = {1.0, 0.5, 0.5, 0.25, 0.25, 0.25};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(got[static_cast<std::size_t>(i)], expected[i], 1e-12);
}

}  // namespace
}  // namespace subdiv
