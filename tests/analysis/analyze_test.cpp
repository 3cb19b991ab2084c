// Scheme analysis against independent computations: the closed forms of
// Loop (eigenvalues, limit mask) and Catmull-Clark (Stam's one-ring matrix
// written out from the formulas, the limit mask n^2 : 4 : 1), the spline
// spectra of the regular cases, and the verdicts.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "subdiv/analysis/analyze.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"

namespace subdiv {
namespace {

Configuration interior(int k) { return {Configuration::Kind::interior, k, CornerType::convex}; }

// Catmull-Clark's matrix on the centre c, edge neighbours e_i and face
// vertices f_i (between e_i and e_(i+1)), from the rules as formulas:
//   c' = (1 - 7/(4k)) c + 3/(2k^2) sum e + 1/(4k^2) sum f
//   e_i' = 3/8 (c + e_i) + 1/16 (e_(i-1) + e_(i+1) + f_(i-1) + f_i)
//   f_i' = (c + e_i + e_(i+1) + f_i) / 4
Eigen::MatrixXd catmull_clark_one_ring(int k) {
  const int n = 2 * k + 1;
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, n);
  auto e = [k](int i) { return 1 + (i % k + k) % k; };
  auto f = [k](int i) { return 1 + k + (i % k + k) % k; };
  const double kk = k;
  S(0, 0) = 1.0 - 7.0 / (4.0 * kk);
  for (int i = 0; i < k; ++i) {
    S(0, e(i)) = 3.0 / (2.0 * kk * kk);
    S(0, f(i)) = 1.0 / (4.0 * kk * kk);
    S(e(i), 0) = S(e(i), e(i)) = 3.0 / 8.0;
    S(e(i), e(i - 1)) = S(e(i), e(i + 1)) = S(e(i), f(i - 1)) = S(e(i), f(i)) = 1.0 / 16.0;
    S(f(i), 0) = S(f(i), e(i)) = S(f(i), e(i + 1)) = S(f(i), f(i)) = 0.25;
  }
  return S;
}

std::vector<double> magnitudes(const Eigen::MatrixXd& S) {
  std::vector<double> out;
  for (const auto& v : S.eigenvalues()) out.push_back(std::abs(v));
  std::sort(out.begin(), out.end(), std::greater<>());
  return out;
}

TEST(Analyze, LoopMatchesItsClosedForms) {
  for (int k = 3; k <= 16; ++k) {
    const ConfigurationAnalysis a = analyze(loop_scheme(), interior(k));
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << "k=" << k << ": " << a.reason;
    ASSERT_EQ(a.leading.size(), 4u);
    const double lambda = 0.375 + 0.25 * std::cos(2.0 * std::numbers::pi / k);
    EXPECT_NEAR(a.leading[0].real(), 1.0, 1e-10);
    EXPECT_NEAR(a.leading[1].real(), lambda, 1e-10) << "k=" << k;
    EXPECT_NEAR(a.leading[2].real(), lambda, 1e-10) << "k=" << k;
    // lambda_3: the largest of 5/8 - k beta, 3/8 + 1/4 cos(4 pi/k) and the
    // 2-ring's own eigenvalues (1/8 and below for Loop's regular rules).
    const double beta = loop_beta(k);
    const double third = std::max({std::fabs(0.625 - k * beta),
                                   k > 3 ? std::fabs(0.375 + 0.25 * std::cos(4.0 * std::numbers::pi / k)) : 0.0, 0.125});
    EXPECT_NEAR(std::abs(a.leading[3]), third, 1e-10) << "k=" << k;
    // Limit mask: beta_limit = 8 beta / (3 + 8 k beta) on each neighbour.
    ASSERT_TRUE(a.limit_mask.has_value());
    const double beta_limit = 8.0 * beta / (3.0 + 8.0 * k * beta);
    EXPECT_NEAR((*a.limit_mask)[0], 1.0 - k * beta_limit, 1e-10);
    for (int i = 1; i <= k; ++i) EXPECT_NEAR((*a.limit_mask)[i], beta_limit, 1e-10);
    // Tangent masks: orthonormal, zero on the centre, orthogonal to constants.
    ASSERT_TRUE(a.tangent_masks.has_value());
    const auto& [t1, t2] = *a.tangent_masks;
    EXPECT_NEAR(t1.dot(t2), 0.0, 1e-10);
    EXPECT_NEAR(t1[0], 0.0, 1e-10);
    EXPECT_NEAR(t1.sum(), 0.0, 1e-10);
  }
}

TEST(Analyze, CatmullClarkMatchesStamsMatrixAndTheLimitMask) {
  for (int k = 3; k <= 16; ++k) {
    const ConfigurationAnalysis a = analyze(catmull_clark_scheme(), interior(k));
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << "k=" << k << ": " << a.reason;
    // The one-ring matrix read off the rules is the formula's, entry for entry
    // (both orders: centre, then ring 1 by angle; the layout puts e_i on ray
    // i and f_i between rays i and i+1, so the ring alternates e, f).
    const Eigen::MatrixXd closed = catmull_clark_one_ring(k);
    Eigen::MatrixXd permuted(closed.rows(), closed.cols());
    std::vector<int> order{0};
    for (int i = 0; i < k; ++i) {
      order.push_back(1 + i);
      order.push_back(1 + k + i);
    }
    for (int r = 0; r < closed.rows(); ++r)
      for (int c = 0; c < closed.cols(); ++c) permuted(r, c) = closed(order[r], order[c]);
    EXPECT_LT((a.matrix.S - permuted).cwiseAbs().maxCoeff(), 1e-15) << "k=" << k;
    const std::vector<double> expected = magnitudes(closed);
    for (int i = 1; i < 4; ++i) EXPECT_NEAR(std::abs(a.leading[static_cast<std::size_t>(i)]), expected[static_cast<std::size_t>(i)], 1e-10) << "k=" << k << " i=" << i;
    // Limit mask n^2 : 4 : 1 over n (n + 5).
    ASSERT_TRUE(a.limit_mask.has_value());
    const double d = k * (k + 5.0);
    EXPECT_NEAR((*a.limit_mask)[0], k * k / d, 1e-10);
    for (int i = 0; i < k; ++i) {
      EXPECT_NEAR((*a.limit_mask)[1 + 2 * i], 4.0 / d, 1e-10);
      EXPECT_NEAR((*a.limit_mask)[2 + 2 * i], 1.0 / d, 1e-10);
    }
  }
}

TEST(Analyze, RegularValencesHaveTheSplineSpectra) {
  // Loop, valence 6 (the quartic box spline): 1, 1/2, 1/2, 1/4, 1/4, 1/4, ...
  const auto loop6 = analyze(loop_scheme(), interior(6)).spectrum.expanded();
  const double loop_expected[] = {1, 0.5, 0.5, 0.25, 0.25, 0.25};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(std::abs(loop6[static_cast<std::size_t>(i)]), loop_expected[i], 1e-10);
  // Catmull-Clark, valence 4 (the bicubic B-spline): 1, 1/2, 1/2, 1/4, 1/4, 1/4, ...
  const ConfigurationAnalysis cc4 = analyze(catmull_clark_scheme(), interior(4));
  const auto cc = cc4.spectrum.expanded();
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(std::abs(cc[static_cast<std::size_t>(i)]), loop_expected[i], 1e-10);
  // lambda^2 = 1/4 is an eigenvalue: bounded curvature (C2 in the regular case).
  EXPECT_EQ(cc4.curvature, CurvatureBehaviour::bounded);
}

TEST(Analyze, WarrensWrongValenceThreeWeightIsCaught) {
  // The survey prints beta = 1/16 at k = 3; then 5/8 - 3/16 = 7/16 is a
  // simple eigenvalue above the pair 1/4: the analysis must not call it C1.
  const Scheme& loop = loop_scheme();
  auto wrong_vertex = [](const LevelView& level, Index v, VertexRule rule, MaskBuilder& mask) {
    const int k = level.topology.valence(v);
    if (k != 3 || rule != VertexRule::smooth) return loop_warren_scheme().masks.vertex_point(level, v, rule, mask);
    mask.add(v, 1.0 - 3.0 / 16.0);
    for (const Index e : level.topology.vertex_edges(v)) mask.add(level.topology.other_vertex(e, v), 1.0 / 16.0);
  };
  const Scheme wrong{.name = "wrong",
                     .split = SplitRule::triangle,
                     .traits = {.needs_triangles = true},
                     .masks = {.edge_point = loop.masks.edge_point, .vertex_point = wrong_vertex}};
  const ConfigurationAnalysis a = analyze(wrong, interior(3));
  EXPECT_NEAR(a.leading[1].real(), 7.0 / 16.0, 1e-10);
  EXPECT_NE(a.verdict, SmoothnessVerdict::c1);
  EXPECT_EQ(a.verdict, SmoothnessVerdict::not_tangent_plane_continuous) << a.reason;
  // With Warren's 3/16 it is C1.
  EXPECT_EQ(analyze(loop_warren_scheme(), interior(3)).verdict, SmoothnessVerdict::c1);
}

TEST(Analyze, WithoutTheRegularRulesTheMasksStayAndC1IsNotClaimed) {
  // Limits and depth bounds read the spectrum and the masks alone: leaving
  // the regular rules' test out must change neither, and must not leave a
  // C1 verdict that rests on half the criterion.
  AnalysisOptions full;
  AnalysisOptions spectral;
  spectral.regular_rules = false;
  for (const Scheme* scheme : {&loop_scheme(), &catmull_clark_scheme()}) {
    const ConfigurationAnalysis a = analyze(*scheme, interior(5), full);
    const ConfigurationAnalysis b = analyze(*scheme, interior(5), spectral);
    ASSERT_EQ(a.verdict, SmoothnessVerdict::c1) << scheme->name;
    EXPECT_EQ(b.verdict, SmoothnessVerdict::inconclusive) << scheme->name;
    EXPECT_NE(b.reason.find("regular rules were not tested"), std::string::npos) << b.reason;
    EXPECT_EQ(b.regular.verdict, SmoothnessVerdict::inconclusive);
    ASSERT_EQ(a.leading.size(), b.leading.size());
    for (std::size_t i = 0; i < a.leading.size(); ++i) EXPECT_EQ(a.leading[i], b.leading[i]) << i;
    ASSERT_TRUE(a.limit_mask && b.limit_mask);
    EXPECT_EQ(*a.limit_mask, *b.limit_mask);
  }
}

}  // namespace
}  // namespace subdiv

namespace subdiv {
namespace {

// With the plain curve rules at the boundary (OpenSubdiv's), regular and
// low-valence boundary vertices are C1, but at higher valences the curve's
// eigenvalue 1/2 stops being subdominant: the reason the survey introduces
// the gamma(theta) edge rule (section 3.2).
TEST(Analyze, PlainBoundaryRulesFailAtHighValence) {
  auto boundary = [](int k) { return Configuration{Configuration::Kind::boundary, k, CornerType::convex}; };
  for (const int k : {2, 3}) EXPECT_EQ(analyze(catmull_clark_scheme(), boundary(k)).verdict, SmoothnessVerdict::c1) << k;
  for (const int k : {3, 4, 5}) EXPECT_EQ(analyze(loop_scheme(), boundary(k)).verdict, SmoothnessVerdict::c1) << k;
  // At Catmull-Clark's k = 4 and Loop's k = 6 the curve's 1/2 ties with
  // another eigenvalue in a Jordan block (checked in exact arithmetic): the
  // eigenvalue condition fails, and the analysis does not claim more.
  for (const auto& [scheme, k] : {std::pair{&catmull_clark_scheme(), 4}, std::pair{&loop_scheme(), 6}}) {
    const ConfigurationAnalysis a = analyze(*scheme, boundary(k));
    EXPECT_FALSE(a.eigenvalue_condition);
    EXPECT_EQ(a.verdict, SmoothnessVerdict::inconclusive) << a.reason;
    EXPECT_NEAR(std::abs(a.leading[2]), 0.5, 1e-10);
    EXPECT_NE(a.reason.find("Jordan block"), std::string::npos) << a.reason;
  }
  for (const int k : {5, 6}) {
    const ConfigurationAnalysis a = analyze(catmull_clark_scheme(), boundary(k));
    EXPECT_NE(a.verdict, SmoothnessVerdict::c1) << k;
    ASSERT_TRUE(a.characteristic_map.has_value());
    EXPECT_FALSE(a.characteristic_map->regular) << k;
    // lambda_1, lambda_2 above the curve's 1/2: their eigenvectors vanish on
    // the boundary curve, which the map sends to the centre.
    EXPECT_NE(a.reason.find("collapses the boundary"), std::string::npos) << a.reason;
  }
  const ConfigurationAnalysis loop7 = analyze(loop_scheme(), boundary(7));
  EXPECT_TRUE(loop7.eigenvalue_condition);
  EXPECT_NEAR(std::abs(loop7.leading[3]), 0.5, 1e-10);
  EXPECT_GT(std::abs(loop7.leading[2]), 0.53);
  EXPECT_NE(loop7.reason.find("collapses the boundary"), std::string::npos) << loop7.reason;
}

}  // namespace
}  // namespace subdiv
