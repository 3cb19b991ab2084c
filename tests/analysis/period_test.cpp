// Schemes whose configurations repeat only after several steps are analysed
// over `period` composed steps. Without such a scheme the machinery is
// proved on Loop, Catmull-Clark and Doo-Sabin with the period forced to 2:
// the matrix must be the square of the period-1 matrix in the same
// neighbourhood order, the eigenvalues squared, the limit and tangent masks
// (left eigenvectors of the same eigenspaces) and every verdict unchanged.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "subdiv/analysis/analyze.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/core/error.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/doo_sabin.h"
#include "subdiv/rules/loop.h"

namespace subdiv {
namespace {

Configuration interior(int k) { return {Configuration::Kind::interior, k, CornerType::convex}; }
Configuration boundary(int k) { return {Configuration::Kind::boundary, k, CornerType::convex}; }

Scheme with_period(const Scheme& scheme, int period) {
  Scheme copy = scheme;
  copy.traits.period = period;
  return copy;
}

void expect_same_layout(const LocalSubdivisionMatrix& a, const LocalSubdivisionMatrix& b, const std::string& what) {
  ASSERT_EQ(a.layout.size(), b.layout.size()) << what;
  for (std::size_t i = 0; i < a.layout.size(); ++i) {
    EXPECT_EQ(a.layout[i].x, b.layout[i].x) << what << " vertex " << i;
    EXPECT_EQ(a.layout[i].y, b.layout[i].y) << what << " vertex " << i;
  }
  EXPECT_EQ(a.ring_of, b.ring_of) << what;
  EXPECT_EQ(a.rotate, b.rotate) << what;
}

void expect_squared(const ConfigurationAnalysis& one, const ConfigurationAnalysis& two, const std::string& what) {
  EXPECT_EQ(one.matrix.period, 1) << what;
  EXPECT_EQ(two.matrix.period, 2) << what;
  EXPECT_EQ(two.matrix.rules.levels, 2) << what;
  ASSERT_EQ(one.matrix.invariant, two.matrix.invariant) << what;
  ASSERT_TRUE(two.matrix.invariant) << what << ": " << two.matrix.invariance_note;
  EXPECT_EQ(one.matrix.rings, two.matrix.rings) << what;
  expect_same_layout(one.matrix, two.matrix, what);
  expect_same_layout(one.wide_matrix, two.wide_matrix, what + " (wide)");
  const Eigen::MatrixXd square = one.matrix.S * one.matrix.S;
  const Eigen::MatrixXd wide_square = one.wide_matrix.S * one.wide_matrix.S;
  EXPECT_LT((two.matrix.S - square).cwiseAbs().maxCoeff(), 1e-14) << what;
  EXPECT_LT((two.wide_matrix.S - wide_square).cwiseAbs().maxCoeff(), 1e-14) << what;

  // The spectrum: each eigenvalue squared, in the same order (squaring
  // keeps the order of magnitudes), with the same algebraic multiplicities.
  const std::vector<std::complex<double>> l1 = one.spectrum.expanded(), l2 = two.spectrum.expanded();
  ASSERT_EQ(l1.size(), l2.size()) << what;
  for (std::size_t i = 0; i < l1.size(); ++i)
    EXPECT_LT(std::abs(l2[i] - l1[i] * l1[i]), 1e-10) << what << " eigenvalue " << i << ": " << l1[i] << "^2 vs " << l2[i];
  ASSERT_EQ(one.leading.size(), two.leading.size()) << what;
  for (std::size_t i = 0; i < one.leading.size(); ++i)
    EXPECT_LT(std::abs(two.leading[i] - one.leading[i] * one.leading[i]), 1e-10) << what << " leading " << i;

  // Left eigenvectors of S are left eigenvectors of S^2 with the squared
  // eigenvalue, normalised alike.
  ASSERT_EQ(one.limit_mask.has_value(), two.limit_mask.has_value()) << what;
  if (one.limit_mask) {
    EXPECT_LT((*one.limit_mask - *two.limit_mask).cwiseAbs().maxCoeff(), 1e-10) << what;
  }
  ASSERT_EQ(one.tangent_masks.has_value(), two.tangent_masks.has_value()) << what;
  if (one.tangent_masks) {
    for (std::size_t t = 0; t < 2; ++t) {
      EXPECT_LT(((*one.tangent_masks)[t] - (*two.tangent_masks)[t]).cwiseAbs().maxCoeff(), 1e-10)
          << what << " tangent " << t;
    }
  }

  EXPECT_EQ(one.eigenvalue_condition, two.eigenvalue_condition) << what;
  EXPECT_EQ(one.verdict, two.verdict) << what << ": " << one.reason << " / " << two.reason;
  EXPECT_EQ(one.curvature, two.curvature) << what;
  ASSERT_EQ(one.characteristic_map.has_value(), two.characteristic_map.has_value()) << what;
  if (one.characteristic_map) {
    EXPECT_EQ(one.characteristic_map->regular, two.characteristic_map->regular) << what;
    EXPECT_EQ(one.characteristic_map->injective, two.characteristic_map->injective) << what;
    // levels analysis steps of two refinement steps each: the same net.
    EXPECT_EQ(one.characteristic_map->image.face_count(), two.characteristic_map->image.face_count()) << what;
    EXPECT_EQ(two.characteristic_map->levels, 2) << what;
  }
}

// The characteristic map of the period-2 analysis over 2 analysis steps is
// refined as far as the period-1 map over 4.
AnalysisOptions options_for(int period) {
  AnalysisOptions options;
  options.characteristic_levels = period == 1 ? 4 : 2;
  return options;
}

TEST(Period, LoopAndCatmullClarkWithPeriodTwoGiveTheSquaredMatrix) {
  for (const Scheme* scheme : {&loop_scheme(), &catmull_clark_scheme()}) {
    const Scheme twice = with_period(*scheme, 2);
    for (int k = 3; k <= 12; ++k) {
      AnalysisOptions o1 = options_for(1), o2 = options_for(2);
      // The characteristic map at a few valences; the rest spectrum and masks.
      o1.characteristic_map = o2.characteristic_map = k <= 6 || k == 12;
      const std::string what = std::string(scheme->name) + " interior k=" + std::to_string(k);
      expect_squared(analyze(*scheme, interior(k), o1), analyze(twice, interior(k), o2), what);
    }
    for (int k = 1; k <= 5; ++k) {
      const std::string what = std::string(scheme->name) + " boundary k=" + std::to_string(k);
      expect_squared(analyze(*scheme, boundary(k), options_for(1)), analyze(twice, boundary(k), options_for(2)), what);
    }
  }
}

TEST(Period, DualSplitLayoutFollowsTwoLevels) {
  // Doo-Sabin's extraordinary faces: child_layout over two levels places
  // each neighbourhood vertex's image at p / 4.
  const Scheme twice = with_period(doo_sabin_scheme(), 2);
  for (int k = 3; k <= 6; ++k) {
    const std::string what = "doo-sabin interior k=" + std::to_string(k);
    expect_squared(analyze(doo_sabin_scheme(), interior(k), options_for(1)), analyze(twice, interior(k), options_for(2)),
                   what);
  }
}

TEST(Period, ChildLayoutOverLevelsIsTheComposedPlacement) {
  for (const SplitRule split : {SplitRule::quad, SplitRule::triangle}) {
    const RingMesh ring = ring_mesh(split, interior(5), 2);
    const std::vector<Vec3> two = child_layout(split, ring, 2);
    // Every layout point p has a descendant at p / 4.
    for (const Vec3& p : ring.mesh.positions) {
      bool found = false;
      for (const Vec3& q : two) found = found || norm(q - 0.25 * p) < 1e-12;
      EXPECT_TRUE(found);
    }
  }
  EXPECT_THROW(child_layout(SplitRule::quad, ring_mesh(SplitRule::quad, interior(4), 1), 0), InvalidInputError);
  const Scheme bad = with_period(loop_scheme(), 0);
  EXPECT_THROW(local_subdivision_matrix(bad, interior(4), 1), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
