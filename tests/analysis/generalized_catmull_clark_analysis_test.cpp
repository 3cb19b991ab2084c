// The analysis of generalized Catmull-Clark schemes against the paper's
// closed forms (Chen and Prautzsch 2012): Example 6.2's mu_0 and
// lambda_{2 pi/m}, Lemma 5.4, Theorem 6.1's verdicts, Lemma 3.2's bound.

#include "subdiv/analysis/generalized_catmull_clark.h"

#include <gtest/gtest.h>

#include <cmath>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/spectrum.h"
#include "subdiv/refine/subdivision_matrix.h"
#include "subdiv/core/error.h"
#include "subdiv/rules/generalized_catmull_clark.h"
#include "subdiv/rules/scheme.h"
#include "support/gcc_schemes.h"

namespace subdiv {
namespace {

using test::gcc;

// The largest eigenvalue magnitude of Fourier frequency f, leaving out 1
// (the affine eigenvalue, frequency 0).
double largest_of_frequency(const Spectrum& s, int f) {
  double best = 0.0;
  for (const Eigenvalue& e : s.values)
    for (const int j : e.frequencies)
      if (j == f && !(f == 0 && std::abs(e.value - 1.0) < 1e-9)) best = std::max(best, std::abs(e.value));
  return best;
}

Spectrum spectrum_at(const Scheme& scheme, int m, int rings) {
  Configuration c;
  c.k = m;
  const LocalSubdivisionMatrix s = local_subdivision_matrix(scheme, c, rings);
  EXPECT_TRUE(s.invariant) << s.invariance_note;
  return spectrum_by_rotation(s.S, {m, s.rotate});
}

const double kGrid[][2] = {{0.25, 0.5}, {0.1, 0.3}, {0.4, 0.2}, {0.05, 0.9}, {0.6, 0.1}, {0.0, 0.5}, {0.3, 0.0}};

TEST(GccClosedForms, EigenvaluesMatchExample62) {
  for (const auto& [alpha, beta] : kGrid) {
    Scheme s = gcc(3, alpha, beta);
    // Non-constant weights too: other values at valences 3, 5 and 7.
    Scheme varied = s;
    std::get<DegreeParameters>(varied.parameters).smoothing[0].valences = {{3, 0.1, 0.6}, {5, 0.5, 0.3}, {7, 0.05, 0.15}};
    for (const Scheme* scheme : {&s, &varied})
      for (int m = 3; m <= 16; ++m) {
        const Spectrum spectrum = spectrum_at(*scheme, m, 1);  // the core: the 1-ring
        const SmoothingWeights& w = std::get<DegreeParameters>(scheme->parameters).smoothing[0];
        const std::complex<double> mu0 = gcc_mu0(w, m);
        EXPECT_NEAR(largest_of_frequency(spectrum, 0), std::abs(mu0), 1e-10)
            << "alpha " << alpha << " beta " << beta << " m " << m;
        EXPECT_NEAR(largest_of_frequency(spectrum, 1), gcc_lambda(w, m), 1e-10)
            << "alpha " << alpha << " beta " << beta << " m " << m;
        EXPECT_NEAR(largest_of_frequency(spectrum, m - 1), gcc_lambda(w, m), 1e-10);
      }
  }
}

TEST(GccClosedForms, LambdaHalfPiIsOneHalf) {
  // Lemma 5.4: frequency f at valence 4f (segment angle pi/2) has 1/2, for any degree and weights.
  for (const auto& [alpha, beta] : kGrid)
    for (int n : {2, 3, 4, 5}) {
      Scheme s = gcc(n, alpha, beta);
      std::get<DegreeParameters>(s.parameters).smoothing[0].valences = {{8, 0.1, 0.2}, {12, 0.7, 0.2}};
      for (int f = 1; f <= 3; ++f) {
        const Spectrum spectrum = spectrum_at(s, 4 * f, (n + 1) / 2 + 1);
        EXPECT_NEAR(largest_of_frequency(spectrum, f), 0.5, 1e-10) << "n " << n << " f " << f;
      }
    }
  // The closed form agrees at m = 4 for every t.
  for (const auto& [alpha, beta] : kGrid) EXPECT_NEAR(gcc_lambda(std::get<DegreeParameters>(gcc(3, alpha, beta).parameters).smoothing[0], 4), 0.5, 1e-15);
}

TEST(GccClosedForms, VerdictsAgreeWithTheorem61) {
  AnalysisOptions options;
  for (const auto& [alpha, beta] : kGrid)
    for (int n : {3, 4, 5}) {
      const Scheme s = gcc(n, alpha, beta);
      for (int m = 5; m <= 9; ++m) {
        Configuration c;
        c.k = m;
        const ConfigurationAnalysis a = analyze(s, c, options);
        EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << "n " << n << " alpha " << alpha << " beta " << beta << " m " << m
                                                    << ": " << a.reason;
        if (n == 3) {
          EXPECT_TRUE(gcc_theorem(s, m).proves_c1);
        }
      }
    }
}

TEST(GccClosedForms, ProvenVerdictsHoldForNonConstantWeights) {
  // Where Remark 5.7's conditions hold (m = 3 and m >= 5 with other weights
  // there than at valence 4), the numerical analysis finds C1 too.
  for (const auto& [alpha, beta] : kGrid) {
    Scheme s = gcc(3, alpha, beta);
    std::get<DegreeParameters>(s.parameters).smoothing[0].valences = {{3, 0.1, 0.6}, {5, 0.5, 0.3}, {7, 0.05, 0.15}};
    for (int m : {3, 5, 7}) {
      const GccTheorem t = gcc_theorem(s, m);
      EXPECT_FALSE(t.constant);
      if (!t.proves_c1) continue;
      Configuration c;
      c.k = m;
      EXPECT_EQ(analyze(s, c).verdict, SmoothnessVerdict::c1) << alpha << " " << beta << " m " << m;
    }
  }
}

TEST(GccClosedForms, Condition52FailsWhereTheNumericsFail) {
  // Non-constant weights: alpha(5) = 0.9, beta(5) = 0.05 make mu_0 = 0.593 >
  // lambda = 0.5500: (5.2) fails, and mu_0 (frequency 0, simple) is the
  // subdominant eigenvalue, so Reif's condition fails.
  Scheme s = gcc(3, 0.25, 0.5);
  std::get<DegreeParameters>(s.parameters).smoothing[0].valences = {{5, 0.9, 0.05}};
  const GccTheorem t = gcc_theorem(s, 5);
  EXPECT_FALSE(t.condition_5_2);
  EXPECT_FALSE(t.proves_c1);
  EXPECT_GT(std::abs(t.mu0), t.lambda);
  Configuration c;
  c.k = 5;
  const ConfigurationAnalysis a = analyze(s, c);
  EXPECT_NE(a.verdict, SmoothnessVerdict::c1);
  EXPECT_FALSE(a.eigenvalue_condition);
  EXPECT_NEAR(std::abs(a.leading[1]), std::abs(t.mu0), 1e-10);
  // The same at valence 3, where (5.1) is the condition: mu_0(3) = 0.592575 > lambda(3) = 0.410097.
  std::get<DegreeParameters>(s.parameters).smoothing[0].valences = {{3, 0.9, 0.05}};
  const GccTheorem t3 = gcc_theorem(s, 3);
  EXPECT_FALSE(t3.condition_5_1);
  EXPECT_FALSE(t3.proves_c1);
  c.k = 3;
  const ConfigurationAnalysis a3 = analyze(s, c);
  EXPECT_NE(a3.verdict, SmoothnessVerdict::c1);
  EXPECT_NEAR(std::abs(a3.leading[1]), std::abs(t3.mu0), 1e-10);
  // The constant neighbours of that set, and Catmull-Clark's weights, are proven.
  EXPECT_TRUE(gcc_theorem(gcc(3, 0.25, 0.5), 5).proves_c1);
  EXPECT_TRUE(gcc_theorem(generalized_catmull_clark_scheme(), 3).proves_c1);
}

TEST(GccClosedForms, RegularSecondDifferenceNorm) {
  // Lemma 3.2 (c): |(B R)_dd| <= max{(2a + b)/4, 1/2 - (2a + b)/4}; the
  // rows the paper lists reach it, so the computed norm equals it.
  for (const auto& [alpha, beta] : kGrid) {
    const Scheme s = gcc(3, alpha, beta);
    const double bound = gcc_second_difference_bound(std::get<DegreeParameters>(s.parameters).smoothing[0]);
    EXPECT_NEAR(regular_second_difference_norm(s), bound, 1e-14) << alpha << " " << beta;
    EXPECT_LT(bound, 0.5);
    // Theorem 3.3: higher degrees are no worse than their first B R.
    for (int n = 4; n <= 7; ++n) EXPECT_LE(regular_second_difference_norm(gcc(n, alpha, beta)), bound + 1e-14) << n;
  }
  // The bicubic B-spline: 1/4.
  EXPECT_NEAR(regular_second_difference_norm(gcc(3, 0.25, 0.5)), 0.25, 1e-15);
}

TEST(GccClosedForms, MidpointDegreeTwoAtExtraordinaryFaces) {
  // M_2 = A R maps a k-gon's corners to 1/2 v_i + 1/8 (v_i-1 + v_i+1) +
  // 1/(4k) sum v: its Fourier transform at frequency 1 is 1/2 + cos(2 pi/k)/4,
  // the subdominant eigenvalue (Prautzsch and Chen 2011 for M_2).
  Scheme s = midpoint_scheme();
  set_degree(s, 2);
  for (int k = 3; k <= 10; ++k) {
    Configuration c;
    c.k = k;
    const ConfigurationAnalysis a = analyze(s, c);
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << k;
    EXPECT_NEAR(a.leading[1].real(), 0.5 + 0.25 * std::cos(2 * M_PI / k), 1e-12) << k;
  }
}

TEST(GccClosedForms, RefusesOtherSchemes) {
  EXPECT_THROW(gcc_theorem(gcc(5, 0.25, 0.5), 5), InvalidInputError);
  EXPECT_THROW(gcc_theorem(gcc(3, 0.25, 0.5), 2), InvalidInputError);
  // Schemes without a degree parameter get the typed error, not a variant's.
  EXPECT_THROW(gcc_theorem(*find_scheme("catmull-clark"), 5), InvalidInputError);
  EXPECT_THROW(gcc_theorem(*find_scheme("quasi-4-8"), 5), InvalidInputError);
}

TEST(GccClosedForms, SecondDifferenceNormOfSchemesWithoutADegree) {
  // Catmull-Clark's regular rule is the bicubic B-spline's: the same 1/4 as
  // gcc of degree 3 with the B-spline's smoothing above.
  EXPECT_NEAR(regular_second_difference_norm(*find_scheme("catmull-clark")), 0.25, 1e-15);
  // Doo-Sabin's is the tensor-product Chaikin mask (1 + z1)^3 (1 + z2)^3 / 16:
  // divided by (1 + z1)^2 it is [1 1] x [1 3 3 1] / 16, by (1 + z1)(1 + z2)
  // [1 2 1] x [1 2 1] / 16; every parity class of either sums to 4/16.
  EXPECT_NEAR(regular_second_difference_norm(*find_scheme("doo-sabin")), 0.25, 1e-15);
  EXPECT_THROW(regular_second_difference_norm(*find_scheme("loop")), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
