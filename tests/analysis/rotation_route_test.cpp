// The routes that make high valences fast agree with the direct ones:
// - the tangent masks' subdominant pair found per Fourier frequency
//   (AnalysisOptions::rotation_rows, taken from 128 rows: valence 360)
//   gives the masks the dense eigensolver gives, checked at valences 3..12;
// - the analysis without masks (the depth bound's) has the same spectrum.

#include <gtest/gtest.h>

#include <limits>

#include "subdiv/analysis/analyze.h"
#include "subdiv/rules/butterfly.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"

namespace subdiv {
namespace {

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).norm() / std::max(a.norm(), b.norm());
}

AnalysisOptions dense_route() {
  AnalysisOptions options;
  options.characteristic_map = false;
  options.rotation_rows = std::numeric_limits<int>::max();
  return options;
}

TEST(RotationRoute, TangentMasksAgreeWithTheDenseRoute) {
  for (const Scheme* scheme : {&catmull_clark_scheme(), &loop_scheme(), &modified_butterfly_scheme()})
    for (int k = 3; k <= 12; ++k) {
      SCOPED_TRACE(std::string(scheme->name) + " valence " + std::to_string(k));
      const Configuration c{Configuration::Kind::interior, k};
      AnalysisOptions fast = dense_route();
      fast.rotation_rows = 0;
      const ConfigurationAnalysis direct = analyze(*scheme, c, dense_route());
      const ConfigurationAnalysis rotated = analyze(*scheme, c, fast);
      ASSERT_FALSE(direct.matrix.rotate.empty());
      ASSERT_TRUE(direct.tangent_masks.has_value());
      ASSERT_TRUE(rotated.tangent_masks.has_value());
      for (int i = 0; i < 2; ++i)
        EXPECT_LT(relative_difference((*direct.tangent_masks)[i], (*rotated.tangent_masks)[i]), 1e-10) << "mask " << i;
      ASSERT_TRUE(direct.limit_mask.has_value());
      EXPECT_EQ(*direct.limit_mask, *rotated.limit_mask);  // the same route for both
      EXPECT_EQ(direct.leading, rotated.leading);
    }
}

TEST(RotationRoute, HighValencesTakeIt) {
  // Valence 360 (OpenSubdiv's catmark_pole360): the dense route took
  // minutes here; the masks still come out and are unit vectors.
  AnalysisOptions options;
  options.characteristic_map = false;
  const ConfigurationAnalysis a = analyze(catmull_clark_scheme(), {Configuration::Kind::interior, 360}, options);
  ASSERT_GE(a.matrix.S.rows(), options.rotation_rows);
  ASSERT_TRUE(a.tangent_masks.has_value());
  EXPECT_NEAR((*a.tangent_masks)[0].norm(), 1.0, 1e-12);
  EXPECT_NEAR((*a.tangent_masks)[1].norm(), 1.0, 1e-12);
  EXPECT_NEAR((*a.tangent_masks)[0].dot((*a.tangent_masks)[1]), 0.0, 1e-10);
}

TEST(RotationRoute, AnalysisWithoutMasksHasTheSameSpectrum) {
  for (const Scheme* scheme : {&catmull_clark_scheme(), &loop_scheme()})
    for (const Configuration c : {Configuration{Configuration::Kind::interior, 5},
                                  Configuration{Configuration::Kind::boundary, 3},
                                  Configuration{Configuration::Kind::corner, 2}}) {
      AnalysisOptions bare = dense_route();
      bare.masks = false;
      const ConfigurationAnalysis full = analyze(*scheme, c, dense_route());
      const ConfigurationAnalysis rates = analyze(*scheme, c, bare);
      EXPECT_EQ(full.leading, rates.leading) << scheme->name << " " << c.name();
      EXPECT_EQ(full.eigenvalue_condition, rates.eigenvalue_condition);
      EXPECT_FALSE(rates.limit_mask.has_value());
      EXPECT_FALSE(rates.tangent_masks.has_value());
    }
}

}  // namespace
}  // namespace subdiv
