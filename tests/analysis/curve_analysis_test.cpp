// Curve schemes through the analysis: the survey's golden 5 x 5 example, and
// the masks read off the eigenvectors against each scheme's closed forms.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "subdiv/analysis/curve_analysis.h"
#include "subdiv/curves/curve_scheme.h"

namespace subdiv {
namespace {

// The closed-form mask as a vector over the neighbourhood: the anchor (the
// centre point, or the left end of the centre edge) at index anchor.
Eigen::VectorXd over_neighbourhood(const CurveMask& mask, Eigen::Index size, Eigen::Index anchor) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(size);
  for (const CurveMaskEntry& e : mask) v[anchor + e.offset] += e.weight;
  return v;
}

TEST(CurveAnalysis, CubicBSplineIsTheSurveysExample) {
  const CurveAnalysis a = analyze_curve(cubic_bspline_curve_scheme());
  // The masks need the 3 points around the centre; the spectrum is that of
  // the survey's 5 x 5 matrix, one point wider on either side.
  ASSERT_EQ(a.half_width, 1);
  ASSERT_EQ(a.wide_S.rows(), 5);
  const double expected[5][5] = {{1, 6, 1, 0, 0}, {0, 4, 4, 0, 0}, {0, 1, 6, 1, 0}, {0, 0, 4, 4, 0}, {0, 0, 1, 6, 1}};
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 5; ++c) EXPECT_EQ(a.wide_S(r, c), expected[r][c] / 8.0) << r << "," << c;
  const double spectrum[5] = {1.0, 0.5, 0.25, 0.125, 0.125};
  const auto all = a.spectrum.expanded();
  ASSERT_EQ(all.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(std::abs(all[i]), spectrum[i], 1e-12);
  ASSERT_TRUE(a.limit_mask && a.tangent_mask);
  const double limit[3] = {1.0 / 6, 2.0 / 3, 1.0 / 6};
  const double tangent[3] = {-0.5, 0, 0.5};  // the survey's (-1, 0, 1), per unit parameter
  for (Eigen::Index i = 0; i < 3; ++i) {
    EXPECT_NEAR((*a.limit_mask)[i], limit[i], 1e-12);
    EXPECT_NEAR((*a.tangent_mask)[i], tangent[i], 1e-12);
  }
  EXPECT_TRUE(a.c1) << a.reason;
}

TEST(CurveAnalysis, MasksMatchTheClosedForms) {
  for (const CurveScheme* scheme : all_curve_schemes()) {
    SCOPED_TRACE(std::string(scheme->name));
    const CurveAnalysis a = analyze_curve(*scheme);
    EXPECT_TRUE(a.c1) << a.reason;
    ASSERT_TRUE(a.limit_mask && a.tangent_mask);
    const Eigen::Index anchor = scheme->dual ? a.half_width - 1 : a.half_width;
    ASSERT_FALSE(scheme->limit.empty());
    EXPECT_LT((*a.limit_mask - over_neighbourhood(scheme->limit, a.S.rows(), anchor)).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((*a.tangent_mask - over_neighbourhood(scheme->tangent, a.S.rows(), anchor)).cwiseAbs().maxCoeff(), 1e-12);
    // Every binary scheme here halves tangents: lambda_1 = 1/2.
    EXPECT_NEAR(a.leading[1].real(), 0.5, 1e-12);
  }
}

// The four-point scheme is C1 for tensions in (0, 1/8) (Dyn, Levin and
// Gregory 1987); at w = 0 it is the piecewise linear interpolant, whose
// lambda_1 = 1/2 is not dominant: 1/2 repeats.
TEST(CurveAnalysis, FourPointTension) {
  EXPECT_TRUE(analyze_curve(four_point_scheme(0.05)).c1);
  const CurveAnalysis linear = analyze_curve(four_point_scheme(0.0));
  EXPECT_FALSE(linear.c1);
  EXPECT_NE(linear.reason.find("lambda"), std::string::npos) << linear.reason;
}

}  // namespace
}  // namespace subdiv
